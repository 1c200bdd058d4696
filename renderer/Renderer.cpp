#include "Renderer.h"

#include "LightFitting.h"
#include "SceneLibrary.h"
#include "SettingsError.h"

#include <QElapsedTimer>

namespace shadowlab {

Renderer::Renderer(GlFunctions* gl)
    : m_gl(gl), m_shadowMap(gl), m_depthPass(gl), m_litPass(gl), m_shadowTimer(gl), m_litTimer(gl)
{
}

Renderer::~Renderer() = default;

void Renderer::setScene(std::optional<Scene> scene)
{
    m_customScene = std::move(scene);
    m_sceneChanged = true;
}

void Renderer::prepareFrame(const Settings& settings, QSize size, TimingMode timing, FrameStats& stats)
{
    ensureValid(settings);
    // Compute everything that can fail before touching state, so a bad value keeps the last frame.
    computeLightFrame(settings.light);
    const bool wantReversed = settings.shadow.enabled && settings.map.format == DepthFormat::Depth32F;
    const bool reversed = wantReversed && m_depthPass.supportsReversedDepth();
    if (wantReversed && !reversed && !m_warnedNoReversedDepth) {
        qWarning("shadowlab: this driver has neither OpenGL 4.5 nor GL_ARB_clip_control; depth32f maps use conventional depth");
        m_warnedNoReversedDepth = true;
    }
    if (settings.shadow.enabled)
        m_shadowMap.ensure(settings.map.size, settings.map.format, reversed);
    if (m_sceneChanged || !m_scene || (!m_customScene && m_scene->scene().name != settings.scene)) {
        m_scene = std::make_unique<GpuScene>(m_gl, m_customScene ? *m_customScene : buildScene(settings.scene));
        m_sceneChanged = false;
        ++m_sceneGeneration;
    }
    const Scene& scene = m_scene->scene();
    const double aspect = double(size.width()) / double(size.height());
    const CameraFrame camera = computeCameraFrame(settings.camera, aspect, scene.bounds());

    // Receivers and casters as the scene's objects say.
    std::vector<FitObject> objects;
    objects.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        objects.push_back({m_scene->objectBounds(i), object.castsShadow, object.receivesShadow, scene.meshes.at(std::size_t(object.mesh)).convex});
    }
    FittedLight fit = fitLight(settings.light, objects, camera.viewProjection, settings.map.size);
    const LightFrame light = computeLightFrame(settings.light, fit.volume, reversed);
    stats.texelWorldSizeBeforeFit = fit.texelBefore;
    stats.texelWorldSize = fit.texelAfter;
    stats.lightFitted = fit.fitted;
    stats.reversedDepth = reversed;

    if (settings.shadow.enabled) {
        const ShadowKey key{m_sceneGeneration, fit.volume, reversed, settings.map.size, settings.map.format,
                            settings.bias.cullFront, settings.bias.polygonFactor, settings.bias.polygonUnits};
        if (m_shadowKey != key && !fit.anythingToShadow) {
            // Nothing can shadow anything seen: no pass, only a map that reads lit everywhere.
            m_depthPass.clear(m_shadowMap, reversed);
            m_shadowKey = key;
            ++m_mapGeneration;
        } else if (m_shadowKey != key) {
            QElapsedTimer wall;
            wall.start();
            m_shadowTimer.begin();
            stats.shadowDraws = m_depthPass.render(*m_scene, light, settings.bias, m_shadowMap);
            m_shadowTimer.end();
            if (timing == TimingMode::Finish) {
                m_gl->glFinish();
                stats.shadowPassWallMs = double(wall.nsecsElapsed()) * 1e-6;
            }
            m_shadowKey = key;
            ++m_mapGeneration;
            stats.shadowPassRendered = true;
            ++m_shadowPassCount;
        }
    }
    // The min/max depth mip follows the map: built after a shadow pass, or when penumbra-only
    // filtering is turned on over a map it was not built from. Timed with the shadow pass.
    if (LitPass::usesDepthRange(settings) && m_depthRangeGeneration != m_mapGeneration) {
        if (!m_depthRange)
            m_depthRange = std::make_unique<DepthRangePass>(m_gl);
        QElapsedTimer wall;
        wall.start();
        m_depthRange->build(m_shadowMap);
        m_depthRangeGeneration = m_mapGeneration;
        if (timing == TimingMode::Finish && stats.shadowPassRendered) {
            m_gl->glFinish();
            stats.shadowPassWallMs += double(wall.nsecsElapsed()) * 1e-6;
        }
    }
    m_fit = std::move(fit);
    m_light = light;
    m_camera = camera;
}

void Renderer::finishTiming(TimingMode timing, FrameStats& stats)
{
    if (timing == TimingMode::Finish) {
        if (stats.shadowPassRendered)
            stats.shadowPassMs = m_shadowTimer.result(true).value_or(0.0);
        stats.litPassMs = m_litTimer.result(true).value_or(0.0);
        return;
    }
    if (auto ms = m_shadowTimer.result(false))
        m_lastShadowMs = *ms;
    if (auto ms = m_litTimer.result(false))
        m_lastLitMs = *ms;
    stats.shadowPassMs = m_lastShadowMs;
    stats.litPassMs = m_lastLitMs;
}

void Renderer::render(const Settings& settings, const RenderTarget& target, TimingMode timing)
{
    if (target.size.width() <= 0 || target.size.height() <= 0) {
        ensureValid(settings);
        return;
    }
    QElapsedTimer frame;
    frame.start();
    FrameStats stats;
    prepareFrame(settings, target.size, timing, stats);

    QElapsedTimer lit;
    lit.start();
    m_litTimer.begin();
    stats.litDraws = m_litPass.render(*m_scene, m_camera, m_light, settings, settings.shadow.enabled ? &m_shadowMap : nullptr, target, false,
                                      m_depthRange.get());
    m_litTimer.end();
    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        stats.litPassWallMs = double(lit.nsecsElapsed()) * 1e-6;
        stats.frameWallMs = double(frame.nsecsElapsed()) * 1e-6;
    }
    finishTiming(timing, stats);
    m_stats = stats;
}

VisibilityBuffer Renderer::renderVisibility(const Settings& settings, QSize size)
{
    if (size.width() <= 0 || size.height() <= 0)
        throw SettingsError(QStringLiteral("size"), QStringLiteral("a measurement needs at least 1x1 pixels"));
    FrameStats stats;
    prepareFrame(settings, size, TimingMode::Finish, stats);
    if (!m_measureTarget)
        m_measureTarget = std::make_unique<MeasureTarget>(m_gl);
    const RenderTarget target = m_measureTarget->ensure(size);
    m_litTimer.begin();
    stats.litDraws = m_litPass.render(*m_scene, m_camera, m_light, settings, settings.shadow.enabled ? &m_shadowMap : nullptr, target,
                                      true, m_depthRange.get());
    m_litTimer.end();
    finishTiming(TimingMode::Finish, stats);
    m_stats = stats;
    return m_measureTarget->read(m_camera.position);
}

std::optional<DepthSpan> Renderer::depthMapSpan()
{
    if (!m_shadowMap.texture())
        return std::nullopt;
    if (!m_depthView)
        m_depthView = std::make_unique<DepthViewPass>(m_gl);
    if (m_spanGeneration != m_mapGeneration) {
        m_span = m_depthView->measure(m_shadowMap, m_light);
        m_spanGeneration = m_mapGeneration;
    }
    return m_span;
}

void Renderer::renderDepthMap(const RenderTarget& target, const QRectF& visible, const QRect& viewport)
{
    if (!m_shadowMap.texture() || target.size.isEmpty())
        return;
    const std::optional<DepthSpan> span = depthMapSpan();
    m_depthView->render(m_shadowMap.texture(), m_light, target, visible, viewport, span);
}

void Renderer::renderDepthLegend(const RenderTarget& target, const QRect& viewport)
{
    if (!m_depthView)
        m_depthView = std::make_unique<DepthViewPass>(m_gl);
    m_depthView->renderLegend(target, viewport);
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
