#include "Renderer.h"

#include "SceneLibrary.h"

#include <QElapsedTimer>

namespace shadowlab {

Renderer::Renderer(GlFunctions* gl)
    : m_gl(gl), m_shadowMap(gl), m_depthPass(gl), m_litPass(gl), m_shadowTimer(gl), m_litTimer(gl)
{
}

Renderer::~Renderer() = default;

void Renderer::render(const Settings& settings, const RenderTarget& target, TimingMode timing)
{
    ensureValid(settings);
    if (target.size.width() <= 0 || target.size.height() <= 0)
        return;

    QElapsedTimer wall;
    wall.start();

    // Compute everything that can fail before touching state, so a bad value keeps the last frame.
    const LightFrame light = computeLightFrame(settings.light);
    if (!m_scene || m_scene->scene().name != settings.scene) {
        m_scene = std::make_unique<GpuScene>(m_gl, buildScene(settings.scene));
        m_shadowKey.reset();
    }
    const double aspect = double(target.size.width()) / double(target.size.height());
    const CameraFrame camera = computeCameraFrame(settings.camera, aspect, m_scene->scene().bounds());

    FrameStats stats;
    stats.texelWorldSize = texelWorldSize(settings.light, settings.map.size);
    if (settings.shadow.enabled) {
        m_shadowMap.ensure(settings.map.size, settings.map.format);
        const ShadowKey key{settings.scene,     settings.light,           settings.map.size,       settings.map.format,
                            settings.bias.cullFront, settings.bias.polygonFactor, settings.bias.polygonUnits};
        if (m_shadowKey != key) {
            m_shadowTimer.begin();
            stats.shadowDraws = m_depthPass.render(*m_scene, light, settings.bias, m_shadowMap);
            m_shadowTimer.end();
            m_shadowKey = key;
            stats.shadowPassRendered = true;
            ++m_shadowPassCount;
        }
    }
    m_light = light;
    m_camera = camera;

    m_litTimer.begin();
    stats.litDraws = m_litPass.render(*m_scene, camera, light, settings, settings.shadow.enabled ? &m_shadowMap : nullptr, target);
    m_litTimer.end();

    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        if (stats.shadowPassRendered)
            stats.shadowPassMs = m_shadowTimer.result(true).value_or(0.0);
        stats.litPassMs = m_litTimer.result(true).value_or(0.0);
        stats.frameWallMs = double(wall.nsecsElapsed()) * 1e-6;
    } else {
        if (auto ms = m_shadowTimer.result(false))
            m_lastShadowMs = *ms;
        if (auto ms = m_litTimer.result(false))
            m_lastLitMs = *ms;
        stats.shadowPassMs = m_lastShadowMs;
        stats.litPassMs = m_lastLitMs;
    }
    m_stats = stats;
}

void Renderer::renderDepthMap(const RenderTarget& target, const QRectF& visible)
{
    if (!m_shadowMap.texture() || target.size.isEmpty())
        return;
    if (!m_depthView)
        m_depthView = std::make_unique<DepthViewPass>(m_gl);
    m_depthView->render(m_shadowMap.texture(), m_light, target, visible);
}

QString Renderer::rendererString() const
{
    const auto text = [this](GLenum name) {
        return QString::fromLatin1(reinterpret_cast<const char*>(m_gl->glGetString(name)));
    };
    return QStringLiteral("%1 (%2, OpenGL %3)").arg(text(GL_RENDERER), text(GL_VENDOR), text(GL_VERSION));
}

int Renderer::maxTextureSize() const
{
    GLint size = 0;
    m_gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    return size;
}

} // namespace shadowlab
