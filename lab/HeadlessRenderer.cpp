#include "HeadlessRenderer.h"

#include "DepthMapPicture.h"
#include "GlDebug.h"
#include "RasteriserTuning.h"
#include "SceneSupply.h"
#include "Limits.h"
#include "RenderError.h"
#include "SettingsError.h"

#include <QGuiApplication>
#include <QPainter>
#include <QOpenGLVersionFunctionsFactory>

namespace shadowlab {

namespace {

constexpr int kMaxTargetSide = kMaxImageSide;

} // namespace

HeadlessRenderer::HeadlessRenderer()
{
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    m_surface.setFormat(format);
    m_surface.create();
    m_context.setFormat(format);
    m_context.setShareContext(QOpenGLContext::globalShareContext());
    if (!m_context.create() || !m_context.makeCurrent(&m_surface))
        throw RenderError(QStringLiteral("cannot create an OpenGL 3.3 core context on platform '%1'")
                              .arg(QGuiApplication::platformName()));
    m_gl = QOpenGLVersionFunctionsFactory::get<GlFunctions>(&m_context);
    if (!m_gl || !m_gl->initializeOpenGLFunctions())
        throw RenderError(QStringLiteral("the OpenGL context does not provide the 3.3 core functions (got %1.%2)")
                              .arg(m_context.format().majorVersion())
                              .arg(m_context.format().minorVersion()));
    installGlDebugLogger();
    m_renderer = std::make_unique<Renderer>(m_gl);
    retainFreedHeapForSoftwareRasteriser(m_renderer->rendererString());
}

HeadlessRenderer::~HeadlessRenderer()
{
    m_context.makeCurrent(&m_surface);
    m_renderer.reset();
    m_framebuffer.reset();
    m_context.doneCurrent();
}

void HeadlessRenderer::makeCurrent()
{
    m_context.makeCurrent(&m_surface);
}

RenderTarget HeadlessRenderer::targetOfSize(QSize size)
{
    if (size.width() < 1 || size.height() < 1 || size.width() > kMaxTargetSide || size.height() > kMaxTargetSide)
        throw SettingsError(QStringLiteral("size"), QStringLiteral("%1x%2 is out of range; width and height must be in [1, %3]")
                                                        .arg(size.width())
                                                        .arg(size.height())
                                                        .arg(kMaxTargetSide));
    makeCurrent();
    if (!m_framebuffer || m_framebuffer->size() != size) {
        m_framebuffer.reset();
        // With stencil, like a window's: the lit pass masks where lookups can find a caster.
        m_framebuffer = std::make_unique<QOpenGLFramebufferObject>(size, QOpenGLFramebufferObject::CombinedDepthStencil, GL_TEXTURE_2D, GL_RGBA8);
        if (!m_framebuffer->isValid()) {
            m_framebuffer.reset();
            throw SettingsError(QStringLiteral("size"), QStringLiteral("the driver cannot make a %1x%2 framebuffer; choose a smaller size")
                                                            .arg(size.width())
                                                            .arg(size.height()));
        }
    }
    return {m_framebuffer->handle(), size};
}

void HeadlessRenderer::renderFrame(const Settings& settings, QSize size, TimingMode timing)
{
    supplyScene(*m_renderer, settings);
    m_renderer->render(settings, targetOfSize(size), timing);
}

QImage HeadlessRenderer::renderScene(const Settings& settings, QSize size, TimingMode timing)
{
    renderFrame(settings, size, timing);
    return m_framebuffer->toImage().convertToFormat(QImage::Format_RGB32);
}

QImage HeadlessRenderer::renderDepthMap(QSize size)
{
    m_renderer->renderDepthMap(targetOfSize(size));
    return m_framebuffer->toImage().convertToFormat(QImage::Format_RGB32);
}

} // namespace shadowlab

namespace shadowlab {

QImage HeadlessRenderer::renderDepthPicture(int side)
{
    const QSize size(side, side + DepthMapPicture::kLegendHeight);
    const RenderTarget target = targetOfSize(size);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    m_gl->glViewport(0, 0, size.width(), size.height());
    m_gl->glClearColor(0.08f, 0.09f, 0.13f, 1.0f);
    m_gl->glClear(GL_COLOR_BUFFER_BIT);
    const DepthMapPicture picture(size);
    const DepthMapFacts facts = depthMapFacts(*m_renderer, m_renderer->depthMapSpan());
    const QRectF visible = picture.homeVisible(facts);
    m_renderer->renderDepthMap(target, visible, picture.glViewport(picture.mapArea(), 1.0));
    m_renderer->renderDepthLegend(target, picture.glViewport(picture.legendBar(), 1.0));
    QImage image = m_framebuffer->toImage().convertToFormat(QImage::Format_RGB32);
    {
        QPainter painter(&image);
        picture.paint(painter, facts, visible);
    }
    // What the legend says, also as PNG text for scripts: the map's size and the written range.
    image.setText(QStringLiteral("map.size"), QString::number(facts.mapSize));
    if (facts.moment > 0) {
        image.setText(QStringLiteral("moments.view"), QString::number(facts.moment));
    } else if (facts.span) {
        image.setText(QStringLiteral("depth.nearest"), QString::number(facts.span->nearest, 'g', 9));
        image.setText(QStringLiteral("depth.farthest"), QString::number(facts.span->farthest, 'g', 9));
    }
    return image;
}

} // namespace shadowlab
