#include "SceneView.h"

#include "GlDebug.h"
#include "LightGizmoPass.h"
#include "Loupe.h"
#include "OrbitCamera.h"
#include "RasteriserTuning.h"
#include "RenderError.h"
#include "Renderer.h"
#include "SceneLibrary.h"
#include "SceneSupply.h"
#include "SettingsError.h"
#include "SharedShaderCode.h"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLVersionFunctionsFactory>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QTimer>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr double kDegreesPerPixel = 0.4;

// The lit pass's density tint (shaders/shared/density_ramp.glsl), for the legend.
QColor densityColour(double pixelsPerTexel)
{
    const glm::vec3 c = glsl::densityRamp(float(pixelsPerTexel));
    return QColor::fromRgbF(c.r, c.g, c.b);
}

// What the texel-density tint means, in the view's bottom-left corner.
void paintDensityLegend(QPainter& painter, const QSize& view)
{
    QFont font = painter.font();
    font.setPixelSize(11);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const QString title = QStringLiteral("screen pixels per shadow texel (red: blocky)");
    const int barWidth = std::max(metrics.horizontalAdvance(title), 180);
    const QRect box(8, view.height() - 8 - (metrics.height() * 2 + 22), barWidth + 16, metrics.height() * 2 + 22);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 22, 28, 200));
    painter.drawRoundedRect(box, 4, 4);
    painter.setPen(QColor(230, 232, 238));
    painter.drawText(QPoint(box.left() + 8, box.top() + 4 + metrics.ascent()), title);
    const QRect bar(box.left() + 8, box.top() + 6 + metrics.height(), barWidth, 10);
    for (int x = 0; x < bar.width(); ++x) {
        const double pixels = std::exp2(-3.0 + 6.0 * (x + 0.5) / bar.width());     // 1/8 ... 8
        painter.fillRect(QRect(bar.left() + x, bar.top(), 1, bar.height()), densityColour(pixels));
    }
    const std::pair<double, const char*> ticks[] = {{0.125, "⅛"}, {1.0, "1"}, {2.0, "2"}, {4.0, "4"}, {8.0, "8+"}};
    for (const auto& [pixels, text] : ticks) {
        const int x = bar.left() + int(std::lround((std::log2(pixels) + 3.0) / 6.0 * bar.width()));
        const QString label = QString::fromUtf8(text);
        const int w = metrics.horizontalAdvance(label);
        painter.drawText(QPoint(std::clamp(x - w / 2, bar.left(), bar.right() - w), bar.bottom() + 2 + metrics.ascent()), label);
    }
}

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
        m_renderer->setVirtualAsyncRequests(true);     // a frame never waits for the GPU's requests
        retainFreedHeapForSoftwareRasteriser(m_renderer->rendererString());    // once, for the process
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
    if (!m_renderer && !m_gizmo && !m_wipeRenderer)
        return;
    makeCurrent();
    m_gizmo.reset();
    m_renderer.reset();
    m_wipeTarget.reset();
    m_wipeRenderer.reset();
    doneCurrent();
}

void SceneView::renderFrame(const Settings& settings)
{
    const QSize size = this->size() * devicePixelRatio();
    const RenderTarget target{defaultFramebufferObject(), size};
    m_renderer->setFitCamera(m_frozenCamera);
    // Finish: per-pass wall times for the status bar; this is a measuring tool, and on a
    // software renderer the frame is CPU work either way.
    supplyScene(*m_renderer, settings);
    m_renderer->render(settings, target, TimingMode::Finish);
    // A virtual map's pages asked for this frame arrive with a later one: draw it, unasked.
    if (m_renderer->lastFrame().virtualPages.requestsPending)
        QTimer::singleShot(0, this, qOverload<>(&SceneView::update));
    std::optional<CameraFrame> frozen;
    if (m_frozenCamera && m_renderer->scene())
        frozen = computeCameraFrame(*m_frozenCamera, double(size.width()) / std::max(1, size.height()), m_renderer->scene()->bounds());
    m_gizmo->render(m_renderer->lightFrame(), m_renderer->cameraFrame(), m_showLightVolume, target, frozen ? &*frozen : nullptr);
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
    if (m_wipe && m_rendered)
        drawWipe();
    if (m_rendered && m_rendered->shading.texelDensity) {
        QOpenGLPaintDevice device(size() * devicePixelRatio());
        device.setDevicePixelRatio(devicePixelRatio());
        QPainter painter(&device);
        paintDensityLegend(painter, size());
    }
    if (!m_errorOverlay.isNull() || (m_wipe && !m_wipeOverlay.isNull())) {
        // On a paint device of the view's framebuffer, not the widget: a widget painter is
        // redirected while the window is grabbed (screenshots), and the GL image covers it.
        QOpenGLPaintDevice device(size() * devicePixelRatio());
        device.setDevicePixelRatio(devicePixelRatio());
        QPainter painter(&device);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        // The camera's field of view is vertical: a frame of another width (compare mode
        // measures both sides at side A's size) matches this view when scaled to its height
        // and centred.
        const auto drawOverlay = [&](const QImage& overlay) {
            if (overlay.isNull())
                return;
            const double scale = double(height()) / overlay.height();
            const double width = overlay.width() * scale;
            painter.drawImage(QRectF((this->width() - width) * 0.5, 0.0, width, height()), overlay);
        };
        // Wiping: each side's errors over its own part of the view.
        const double divider = m_wipe ? m_wipePosition * width() : width();
        painter.setClipRect(QRectF(0.0, 0.0, divider, height()));
        drawOverlay(m_errorOverlay);
        if (m_wipe && !m_wipeOverlay.isNull()) {
            painter.setClipRect(QRectF(divider, 0.0, width() - divider, height()));
            drawOverlay(m_wipeOverlay);
        }
    }
    if (m_wipe && m_rendered)
        paintWipeDivider();
    if (m_loupe) {
        // The frame as shown (the overlay included), for the loupe to magnify between frames.
        const QSize size = this->size() * devicePixelRatio();
        QImage frame(size, QImage::Format_RGBA8888);
        context()->functions()->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
        context()->functions()->glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_UNSIGNED_BYTE, frame.bits());
        m_loupeFrame = frame.mirrored().convertToFormat(QImage::Format_RGB32);
        if (m_loupe->isVisible())
            m_loupe->showAt(m_lastMouse, m_loupeFrame, devicePixelRatio());
    }
    m_lastFrameMs = double(timer.nsecsElapsed()) * 1e-6;
    ++m_frameCount;
    emit frameRendered();
}

void SceneView::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    setFocus(Qt::MouseFocusReason);
    // The wipe's divider is dragged, not the camera; a press on its right selects the other side.
    m_draggingWipe = event->button() == Qt::LeftButton && nearWipeDivider(m_lastMouse);
    if (m_wipe && m_lastMouse.x() > m_wipePosition * width() && !m_draggingWipe)
        emit wipeSideActivated();
    else
        emit activated();
}

void SceneView::setWipe(const std::optional<Settings>& other)
{
    if (other == m_wipe)
        return;
    m_wipe = other;
    if (!m_wipe && (m_wipeRenderer || m_wipeTarget)) {
        // Its caches and framebuffer go with it; they come back when the wipe does.
        makeCurrent();
        m_wipeTarget.reset();
        m_wipeRenderer.reset();
        doneCurrent();
    }
    setMouseTracking(m_wipe.has_value() || m_loupe != nullptr);
    update();
}

void SceneView::setFrozenCamera(const std::optional<CameraSettings>& camera)
{
    if (camera == m_frozenCamera)
        return;
    m_frozenCamera = camera;
    update();
}

void SceneView::setWipeOverlay(const QImage& image)
{
    if (image.isNull() && m_wipeOverlay.isNull())
        return;
    m_wipeOverlay = image;
    if (m_wipe)
        update();
}

void SceneView::setWipePosition(double position)
{
    position = std::clamp(position, 0.0, 1.0);
    if (position == m_wipePosition)
        return;
    m_wipePosition = position;
    update();
}

void SceneView::drawWipe()
{
    const QSize size = this->size() * devicePixelRatio();
    try {
        if (!m_wipeRenderer) {
            auto* gl = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context());
            m_wipeRenderer = std::make_unique<Renderer>(gl);
            m_wipeRenderer->setVirtualAsyncRequests(true);
        }
        if (!m_wipeTarget || m_wipeTarget->size() != size)
            m_wipeTarget = std::make_unique<QOpenGLFramebufferObject>(size, QOpenGLFramebufferObject::CombinedDepthStencil, GL_TEXTURE_2D, GL_RGBA8);
        m_wipeRenderer->setFitCamera(m_frozenCamera);
        supplyScene(*m_wipeRenderer, *m_wipe);
        m_wipeRenderer->render(*m_wipe, RenderTarget{m_wipeTarget->handle(), size}, TimingMode::Finish);
    } catch (const std::runtime_error& e) {
        const auto* settingsError = dynamic_cast<const SettingsError*>(&e);
        emit renderFailed(settingsError ? settingsError->key() : QString(), QString::fromStdString(e.what()));
        return;
    }
    // The other side's pixels right of the divider, over this side's frame.
    const int x = int(std::lround(m_wipePosition * size.width()));
    auto* gl = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context());
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_wipeTarget->handle());
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    gl->glBlitFramebuffer(x, 0, size.width(), size.height(), x, 0, size.width(), size.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
}

void SceneView::paintWipeDivider()
{
    // The divider, and which side is which, over everything else.
    QOpenGLPaintDevice device(size() * devicePixelRatio());
    device.setDevicePixelRatio(devicePixelRatio());
    QPainter painter(&device);
    const double at = m_wipePosition * width();
    painter.setPen(QPen(QColor(0, 0, 0, 160), 3));
    painter.drawLine(QPointF(at, 0.0), QPointF(at, height()));
    painter.setPen(QPen(QColor(255, 255, 255), 1));
    painter.drawLine(QPointF(at, 0.0), QPointF(at, height()));
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    const QRectF handle(at - 9.0, height() * 0.5 - 16.0, 18.0, 32.0);
    painter.setBrush(QColor(245, 246, 250));
    painter.setPen(QPen(QColor(40, 44, 56), 1));
    painter.drawRoundedRect(handle, 4.0, 4.0);
    painter.setPen(QColor(255, 255, 255));
    painter.drawText(QRectF(at - 40.0, 6.0, 32.0, 18.0), Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("A"));
    painter.drawText(QRectF(at + 8.0, 6.0, 32.0, 18.0), Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("B"));
}

bool SceneView::nearWipeDivider(const QPoint& position) const
{
    return m_wipe && std::abs(position.x() - m_wipePosition * width()) <= 8.0;
}

void SceneView::mouseReleaseEvent(QMouseEvent* event)
{
    m_draggingWipe = false;
    QOpenGLWidget::mouseReleaseEvent(event);
}

void SceneView::setLoupe(bool on)
{
    if (on == loupe())
        return;
    if (on) {
        m_loupe = new Loupe(this);
    } else {
        delete m_loupe;
        m_loupe = nullptr;
        m_loupeFrame = QImage();
    }
    setMouseTracking(on || m_wipe.has_value());
    update();   // one frame to read back
}

void SceneView::leaveEvent(QEvent* event)
{
    if (m_loupe)
        m_loupe->hide();
    QOpenGLWidget::leaveEvent(event);
}

void SceneView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    if (m_loupe)
        m_loupe->showAt(position, m_loupeFrame, devicePixelRatio());
    if (m_wipe) {
        setCursor(m_draggingWipe || nearWipeDivider(position) ? Qt::SplitHCursor : Qt::ArrowCursor);
        if (m_draggingWipe) {
            m_lastMouse = position;
            setWipePosition(double(position.x()) / std::max(1, width()));
            return;
        }
    }
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (delta.isNull())
        return;
    // Ctrl+drag turns the light around its target as a left drag orbits the camera: right is
    // further round, up is higher.
    if ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ControlModifier)) {
        emit lightTurned(delta.x() * kDegreesPerPixel, -delta.y() * kDegreesPerPixel);
        return;
    }
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
            emit cameraEdited(presetCamera(m_settings.scene, aspect()));
        } catch (const SettingsError& e) {
            // The scene's file changed or went away since it was loaded: keep the camera.
            emit renderFailed(e.key(), QString::fromUtf8(e.what()));
        }
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void SceneView::redrawCachedShadows()
{
    if (m_renderer)
        m_renderer->requestShadowRedraw();
    update();
}

void SceneView::redrawForMeasurement()
{
    if (m_renderer)
        m_renderer->invalidateShadowMap();
    update();
}

} // namespace shadowlab
