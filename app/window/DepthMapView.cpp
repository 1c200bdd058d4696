#include "DepthMapView.h"

#include "DepthMapPicture.h"
#include "DepthViewPass.h"
#include "GlDebug.h"
#include "RenderError.h"
#include "Renderer.h"
#include "SceneView.h"
#include "ShadowTechnique.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QPixmap>
#include <QPolygonF>

#include <tuple>
#include <utility>
#include <QOpenGLVersionFunctionsFactory>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr double kZoomPerStep = 1.25;
constexpr double kMinZoom = 0.25;
constexpr double kMaxZoom = 256.0;

} // namespace

DepthMapView::DepthMapView(QWidget* parent) : QOpenGLWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
}

DepthMapView::~DepthMapView()
{
    cleanup();
    // The base class destroys the context (which signals aboutToBeDestroyed) and the source
    // view may still signal a frame: neither may reach this half-destroyed object.
    disconnect(m_sourceConnection);
    if (context())
        disconnect(context(), nullptr, this, nullptr);
}

void DepthMapView::setSource(SceneView* source)
{
    if (source == m_source)
        return;
    disconnect(m_sourceConnection);
    m_source = source;
    if (source)
        m_sourceConnection = connect(source, &SceneView::frameRendered, this, &DepthMapView::onSourceFrame);
    m_seenMapGeneration = -1;
    m_spanMapGeneration = -1;
    update();
}

void DepthMapView::onSourceFrame()
{
    // A new shadow pass changes the map, a camera move the outline of what the camera sees.
    const Renderer* renderer = m_source ? m_source->renderer() : nullptr;
    const int passes = renderer ? renderer->mapGeneration() : -1;
    const Settings* settings = m_source && m_source->renderedSettings() ? &*m_source->renderedSettings() : nullptr;
    const bool enabled = settings && settings->shadow.enabled;
    const std::optional<glm::dmat4> camera = renderer ? std::optional(renderer->cameraFrame().viewProjection) : std::nullopt;
    // A moment technique's view also changes with the moment shown.
    const int momentView = settings ? int(settings->filter.mode) * 8 + settings->moments.view : 0;
    if (passes == m_seenMapGeneration && enabled == m_seenShadowsEnabled && camera == m_seenCamera && momentView == m_seenMomentView)
        return;
    m_seenMapGeneration = passes;
    m_seenShadowsEnabled = enabled;
    m_seenCamera = camera;
    m_seenMomentView = momentView;
    update();
}

bool DepthMapView::hasMap() const
{
    return m_source && m_source->renderer() && m_source->renderer()->shadowMap().texture() && m_source->renderedSettings()
        && m_source->renderedSettings()->shadow.enabled;
}

void DepthMapView::initializeGL()
{
    m_gl = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context());
    if (!m_gl || !m_gl->initializeOpenGLFunctions()) {
        m_gl = nullptr;
        return;
    }
    installGlDebugLogger();
    try {
        m_pass = std::make_unique<DepthViewPass>(m_gl);
    } catch (const RenderError& e) {
        qWarning("depth-map view: %s", e.what());
        return;
    }
    m_readFramebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_readFramebuffer.id());
    labelGlObject(GlLabelKind::Framebuffer, m_readFramebuffer.id(), QStringLiteral("depth-map view: texel read-back"));
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, defaultFramebufferObject());
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &DepthMapView::cleanup, Qt::UniqueConnection);
}

void DepthMapView::cleanup()
{
    if (!m_pass && !m_readFramebuffer)
        return;
    makeCurrent();
    m_pass.reset();
    m_readFramebuffer.reset();
    doneCurrent();
}

void DepthMapView::paintGL()
{
    if (!m_gl)
        return;
    m_gl->glClearColor(0.08f, 0.09f, 0.13f, 1.0f);
    m_gl->glClear(GL_COLOR_BUFFER_BIT);
    if (m_pass && hasMap()) {
        const Renderer& renderer = *m_source->renderer();
        // The stretch is measured here, in this context, once per shadow pass.
        if (m_spanMapGeneration != renderer.mapGeneration()) {
            m_span = m_pass->measure(renderer.shadowMap(), renderer.lightFrame());
            m_spanMapGeneration = renderer.mapGeneration();
        }
        const DepthMapPicture picture(size());
        const RenderTarget target{defaultFramebufferObject(), size() * devicePixelRatio()};
        const QRectF visible = visibleRect();
        if (showsMoments())
            m_pass->renderMoments(renderer.momentsMap()->texture(), *m_source->renderedSettings(), target, visible,
                                  picture.glViewport(picture.mapArea(), devicePixelRatio()));
        else
            m_pass->render(renderer.shadowMap(), renderer.lightFrame(), target, visible,
                           picture.glViewport(picture.mapArea(), devicePixelRatio()), m_span);
        m_pass->renderLegend(target, picture.glViewport(picture.legendBar(), devicePixelRatio()));
        // Text and outlines through QPainter's raster engine, blended over the map as one image.
        QImage overlay(target.size, QImage::Format_ARGB32_Premultiplied);
        overlay.fill(Qt::transparent);
        overlay.setDevicePixelRatio(devicePixelRatio());
        {
            QPainter painter(&overlay);
            picture.paint(painter, depthMapFacts(renderer, m_span, m_pointer), visible);
        }
        m_pass->renderOverlay(target, overlay);
    }
    ++m_frameCount;
    emit frameRendered();
}

QRectF DepthMapView::visibleRect() const
{
    const Renderer* renderer = m_source && hasMap() ? m_source->renderer() : nullptr;
    const DepthMapPicture picture(size());
    if (!renderer)
        return picture.visible(1.0, m_zoom, m_center);
    const DepthMapFacts facts = depthMapFacts(*renderer, m_span);
    return m_framing == Framing::Free ? picture.visible(facts.aspect, m_zoom, m_center) : picture.regionVisible(facts, framedRegion());
}

QRectF DepthMapView::framedRegion() const
{
    if (m_framing == Framing::Footprint && m_source && hasMap())
        return DepthMapPicture::footprintRegion(depthMapFacts(*m_source->renderer(), m_span));
    return DepthMapPicture::homeRegion();
}

void DepthMapView::leaveHome()
{
    if (m_framing == Framing::Free)
        return;
    if (m_source && hasMap()) {
        const DepthMapPicture picture(size());
        const DepthMapFacts facts = depthMapFacts(*m_source->renderer(), m_span);
        std::tie(m_zoom, m_center) = picture.framing(facts.aspect, framedRegion());
    }
    m_framing = Framing::Free;
}

QPointF DepthMapView::mapPoint(QPointF p) const
{
    return DepthMapPicture(size()).toMap(p, visibleRect());
}

std::optional<DepthSpan> DepthMapView::shownSpan() const
{
    return m_span;
}

void DepthMapView::resetZoom()
{
    m_framing = Framing::Map;
    update();
}

void DepthMapView::frameFootprint()
{
    m_framing = Framing::Footprint;
    update();
}

std::optional<float> DepthMapView::readDepth(int x, int y)
{
    if (!m_readFramebuffer || !hasMap())
        return std::nullopt;
    // Framebuffers are per context, textures shared: attach the map to one of ours and read
    // one texel, instead of copying the whole map back.
    makeCurrent();
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_readFramebuffer.id());
    m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                 m_source->renderer()->shadowMap().texture(), 0);
    m_gl->glReadBuffer(GL_NONE);
    std::optional<float> depth;
    if (m_gl->glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        float value = 0.0f;
        m_gl->glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &value);
        depth = float(m_source->renderer()->shadowMap().slice().depth(value));
    }
    m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, defaultFramebufferObject());
    doneCurrent();
    return depth;
}

bool DepthMapView::showsMoments() const
{
    return hasMap() && m_source->renderer()->depthMapMoment() > 0;
}

std::optional<std::array<float, 4>> DepthMapView::readMoments(int x, int y)
{
    if (!m_readFramebuffer || !showsMoments())
        return std::nullopt;
    makeCurrent();
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_readFramebuffer.id());
    m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                 m_source->renderer()->momentsMap()->texture(), 0);
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    std::optional<std::array<float, 4>> moments;
    if (m_gl->glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        std::array<float, 4> value{};
        m_gl->glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, value.data());
        moments = value;
    }
    m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, defaultFramebufferObject());
    doneCurrent();
    return moments;
}

void DepthMapView::reportTexel(QPointF widgetPosition)
{
    if (!hasMap()) {
        emit texelHovered(QString());
        return;
    }
    const Renderer& renderer = *m_source->renderer();
    // Map coordinates span the whole texture, every view's tile of it.
    const int width = renderer.shadowMap().width(), height = renderer.shadowMap().height();
    const QPointF uv = mapPoint(widgetPosition);
    const int x = int(std::floor(uv.x() * width));
    const int y = int(std::floor(uv.y() * height));
    if (x < 0 || y < 0 || x >= width || y >= height) {
        emit texelHovered(QString());
        return;
    }
    if (showsMoments()) {
        // The moments as stored (after the blur pass, where moments.blur_at runs one), which the
        // lit pass filters.
        if (const auto m = readMoments(x, y))
            emit texelHovered(QStringLiteral("texel %1, %2 · moments %3, %4, %5, %6")
                                  .arg(x).arg(y).arg((*m)[0], 0, 'g', 5).arg((*m)[1], 0, 'g', 5).arg((*m)[2], 0, 'g', 5).arg((*m)[3], 0, 'g', 5));
        else
            emit texelHovered(QStringLiteral("texel %1, %2").arg(x).arg(y));
        return;
    }
    const std::optional<float> depth = readDepth(x, y);
    if (!depth) {
        emit texelHovered(QStringLiteral("texel %1, %2").arg(x).arg(y));
        return;
    }
    // Distance from the light along its axis: depth is linear for an ortho light, and the
    // perspective depth curve inverted for a perspective one (or the warp, at this texel).
    const LightFrame& light = renderer.lightFrame();
    const double d = *depth;
    const double distance = depthToDistance(light, d, glm::dvec2((x + 0.5) / width, (y + 0.5) / height));
    const QString where = d >= 1.0 ? QStringLiteral("empty (far plane)")
                                   : QStringLiteral("%1 from the light").arg(distance, 0, 'f', 3);
    QString text = QStringLiteral("texel %1, %2 · depth %3 · %4").arg(x).arg(y).arg(d, 0, 'f', 5).arg(where);
    if (const std::optional<VirtualPoolFacts> pool = virtualPoolFacts(renderer)) {
        if (const std::optional<int> slot = poolSlotAt(pool->poolSide, uv))
            text += QStringLiteral(" · ") + virtualSlotText(*pool, *slot);
    }
    emit texelHovered(text);
}

void DepthMapView::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position();
    setFocus(Qt::MouseFocusReason);
}

void DepthMapView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF position = event->position();
    if (event->buttons() != Qt::NoButton) {
        leaveHome();
        const QPointF delta = position - m_lastMouse;
        const double perPixel = visibleRect().height() / std::max(1, DepthMapPicture(size()).mapArea().height());
        m_center += QPointF(-delta.x() * perPixel, delta.y() * perPixel);
        update();
    }
    m_lastMouse = position;
    m_pointer = mapPoint(position);
    // A virtual pool marks the slot under the pointer and shows its level's page table.
    if (hasMap() && m_source->renderer()->lastFrame().virtualMap)
        update();
    reportTexel(position);
}

void DepthMapView::mouseDoubleClickEvent(QMouseEvent*)
{
    resetZoom();
}

void DepthMapView::wheelEvent(QWheelEvent* event)
{
    // Zoom about the cursor: the map point under it stays under it.
    const QPointF position = event->position();
    leaveHome();
    const QPointF before = mapPoint(position);
    m_zoom = std::clamp(m_zoom * std::pow(kZoomPerStep, event->angleDelta().y() / 120.0), kMinZoom, kMaxZoom);
    m_center += before - mapPoint(position);
    update();
    reportTexel(position);
}

void DepthMapView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Home || event->key() == Qt::Key_0) {
        resetZoom();
        return;
    }
    if (event->key() == Qt::Key_F) {
        frameFootprint();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void DepthMapView::leaveEvent(QEvent* event)
{
    if (std::exchange(m_pointer, std::nullopt) && hasMap() && m_source->renderer()->lastFrame().virtualMap)
        update();
    emit texelHovered(QString());
    QOpenGLWidget::leaveEvent(event);
}

QIcon DepthMapView::framingIcon(bool withFootprint)
{
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor light(225, 228, 235);
    painter.setPen(QPen(light, 2.5));
    if (withFootprint) {
        painter.drawRect(QRectF(11, 11, 10, 10));
        painter.setPen(QPen(QColor(255, 150, 40), 2.5));
        painter.drawPolygon(QPolygonF{QPointF(4, 28), QPointF(28, 28), QPointF(22, 4), QPointF(10, 4)});
    } else {
        painter.drawRect(QRectF(7, 7, 18, 18));
        for (const QPointF corner : {QPointF(2, 2), QPointF(30, 2), QPointF(30, 30), QPointF(2, 30)}) {
            const QPointF in((corner.x() < 16 ? 1 : -1) * 6.0, (corner.y() < 16 ? 1 : -1) * 6.0);
            painter.drawLine(corner, corner + QPointF(in.x(), 0));
            painter.drawLine(corner, corner + QPointF(0, in.y()));
        }
    }
    return QIcon(pixmap);
}

} // namespace shadowlab
