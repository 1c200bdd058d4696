#include "SceneView.h"

#include "GlDebug.h"
#include "LightGizmoPass.h"
#include "OrbitCamera.h"
#include "RenderError.h"
#include "Renderer.h"
#include "SceneLibrary.h"
#include "SettingsError.h"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLVersionFunctionsFactory>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QWheelEvent>

namespace shadowlab {

namespace {

constexpr double kDegreesPerPixel = 0.4;

} // namespace

SceneView::SceneView(QWidget* parent) : QOpenGLWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(0, 0);
}

SceneView::~SceneView()
{
    cleanup();
    // The base class destroys the context, which signals aboutToBeDestroyed: that must not
    // reach this half-destroyed object.
    if (context())
        disconnect(context(), nullptr, this, nullptr);
}

void SceneView::setSettings(const Settings& settings)
{
    if (settings == m_settings)
        return;
    m_settings = settings;
    update();
}

void SceneView::setShowLightVolume(bool show)
{
    if (show == m_showLightVolume)
        return;
    m_showLightVolume = show;
    update();
}

void SceneView::setErrorOverlay(const QImage& image)
{
    if (image.isNull() && m_errorOverlay.isNull())
        return;
    m_errorOverlay = image;
    update();
}

void SceneView::initializeGL()
{
    auto* gl = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context());
    if (!gl || !gl->initializeOpenGLFunctions()) {
        emit renderFailed(QString(), QStringLiteral("this OpenGL context does not provide OpenGL 3.3 core"));
        return;
    }
    installGlDebugLogger();
    try {
        m_renderer = std::make_unique<Renderer>(gl);
        m_gizmo = std::make_unique<LightGizmoPass>(gl);
    } catch (const RenderError& e) {
        m_renderer.reset();
        emit renderFailed(QString(), QString::fromStdString(e.what()));
        return;
    }
    m_rendered.reset();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &SceneView::cleanup, Qt::UniqueConnection);
}

void SceneView::cleanup()
{
    if (!m_renderer && !m_gizmo)
        return;
    makeCurrent();
    m_gizmo.reset();
    m_renderer.reset();
    doneCurrent();
}

void SceneView::renderFrame(const Settings& settings)
{
    const QSize size = this->size() * devicePixelRatio();
    const RenderTarget target{defaultFramebufferObject(), size};
    // Finish: per-pass wall times for the status bar; this is a measuring tool, and on a
    // software renderer the frame is CPU work either way.
    m_renderer->render(settings, target, TimingMode::Finish);
    m_gizmo->render(m_renderer->lightFrame(), m_renderer->cameraFrame(), m_showLightVolume, target);
}

void SceneView::paintGL()
{
    if (!m_renderer)
        return;
    QElapsedTimer timer;
    timer.start();
    try {
        renderFrame(m_settings);
        m_rendered = m_settings;
    } catch (const std::runtime_error& e) {
        // SettingsError (names its key) or RenderError: keep showing what worked last.
        const auto* settingsError = dynamic_cast<const SettingsError*>(&e);
        emit renderFailed(settingsError ? settingsError->key() : QString(), QString::fromStdString(e.what()));
        if (m_rendered) {
            try {
                renderFrame(*m_rendered);
            } catch (const std::runtime_error&) {
                m_rendered.reset();
            }
        }
    }
    if (!m_errorOverlay.isNull()) {
        // On a paint device of the view's framebuffer, not the widget: a widget painter is
        // redirected while the window is grabbed (screenshots), and the GL image covers it.
        QOpenGLPaintDevice device(size() * devicePixelRatio());
        device.setDevicePixelRatio(devicePixelRatio());
        QPainter painter(&device);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        // The camera's field of view is vertical: a frame of another width (compare mode
        // measures both sides at side A's size) matches this view when scaled to its height
        // and centred.
        const double scale = double(height()) / m_errorOverlay.height();
        const double width = m_errorOverlay.width() * scale;
        painter.drawImage(QRectF((this->width() - width) * 0.5, 0.0, width, height()), m_errorOverlay);
    }
    m_lastFrameMs = double(timer.nsecsElapsed()) * 1e-6;
    ++m_frameCount;
    emit frameRendered();
}

void SceneView::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    setFocus(Qt::MouseFocusReason);
    emit activated();
}

void SceneView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (delta.isNull())
        return;
    OrbitCamera camera(m_settings.camera, groundHeight());
    if (event->buttons() & Qt::LeftButton)
        camera.orbit(delta.x() * kDegreesPerPixel, delta.y() * kDegreesPerPixel);
    else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton))
        camera.pan(QPointF(delta), size());
    else
        return;
    emit cameraEdited(camera.settings());
}

void SceneView::wheelEvent(QWheelEvent* event)
{
    OrbitCamera camera(m_settings.camera, groundHeight());
    camera.zoom(event->angleDelta().y() / 120.0);
    emit cameraEdited(camera.settings());
}

std::optional<double> SceneView::groundHeight() const
{
    const Scene* scene = m_renderer ? m_renderer->scene() : nullptr;
    return scene ? scene->groundHeight : std::nullopt;
}

void SceneView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_R || event->key() == Qt::Key_Home) {
        try {
            emit cameraEdited(presetSettings(m_settings.scene).camera);
        } catch (const SettingsError& e) {
            // The scene's file changed or went away since it was loaded: keep the camera.
            emit renderFailed(e.key(), QString::fromUtf8(e.what()));
        }
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void SceneView::redrawForMeasurement()
{
    if (m_renderer)
        m_renderer->invalidateShadowMap();
    update();
}

} // namespace shadowlab
