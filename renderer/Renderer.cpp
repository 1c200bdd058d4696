#include "Renderer.h"

#include "LightFitting.h"
#include "MomentMath.h"
#include "ShadowTechnique.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "ShadowViews.h"

#include <algorithm>

#include <QElapsedTimer>

namespace shadowlab {

Renderer::Renderer(GlFunctions* gl)
    : m_gl(gl), m_shadowMap(gl), m_depthPass(gl), m_depthStorage(makeDepthStorage(m_shadowMap, m_depthPass)), m_litPass(gl),
      m_shadowTimer(gl), m_litTimer(gl)
{
}

const MomentsMap* Renderer::momentsMap() const
{
    return m_momentsStorage ? m_momentsStorage->momentsMap() : nullptr;
}

const MomentsMap* Renderer::momentsShown() const
{
    return m_viewSettings.shadow.enabled ? storageFor(m_viewSettings).momentsMap() : nullptr;
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
    ShadowStorage& storage = storageFor(settings);
    // A moments map keeps its precision in its own format; its pass uses conventional depth.
    const bool wantReversed = settings.shadow.enabled && settings.map.format == DepthFormat::Depth32F && !storage.momentsMap();
    const bool reversed = wantReversed && m_depthPass.supportsReversedDepth();
    if (wantReversed && !reversed && !m_warnedNoReversedDepth) {
        qWarning("shadowlab: this driver has neither OpenGL 4.5 nor GL_ARB_clip_control; depth32f maps use conventional depth");
        m_warnedNoReversedDepth = true;
    }
    const bool virtualMap = settings.shadow.enabled && settings.shadow.virtualMap;
    // A virtual map's pool is the map: a slot per page, poolSide² of them.
    const ShadowTileGrid grid = virtualMap ? ShadowTileGrid{settings.shadow.virtualPool, settings.shadow.virtualPool} : shadowTileGrid(settings);
    if (virtualMap && settings.shadow.virtualPool * kVirtualSlotTexels > maxTextureSize())
        throw SettingsError(QStringLiteral("shadow.virtual_pool"),
                            QStringLiteral("a pool of %1² pages needs a %2² texture, and this driver allows %3² at most; lower shadow.virtual_pool")
                                .arg(settings.shadow.virtualPool).arg(settings.shadow.virtualPool * kVirtualSlotTexels).arg(maxTextureSize()));
    if (settings.shadow.enabled) {
        m_shadowMap.ensureTiles(virtualMap ? kVirtualSlotTexels : settings.map.size, grid.columns, grid.rows, settings.map.format, reversed);
        storage.ensure(settings, grid);
    }
    if (m_sceneChanged || !m_scene || (!m_customScene && m_scene->scene().name != settings.scene)) {
        m_scene = std::make_unique<GpuScene>(m_gl, m_customScene ? *m_customScene : buildScene(settings.scene));
        m_sceneChanged = false;
        ++m_sceneGeneration;
    }
    const double aspect = double(size.width()) / double(size.height());
    const CameraFrame camera = computeCameraFrame(settings.camera, aspect, m_scene->bounds());
    m_camera = camera;

    // The fit is a pure function of the scene, the settings, the fitting camera and the frame's
    // size: when none of them changed (a still frame, a window repaint), the last one stands.
    // For the city that is 2,000 objects clipped against the view each frame, left out.
    FitInputs inputs{m_sceneGeneration, settings, m_fitCamera, size, reversed};
    if (!m_fitInputs || !(*m_fitInputs == inputs)) {
        const CameraFrame fitCamera = m_fitCamera ? computeCameraFrame(*m_fitCamera, aspect, m_scene->bounds()) : camera;
        // Sample-distribution cascades split the depth range the fitting camera draws.
        m_visibleRange.reset();
        if (usesVisibleDepth(settings)) {
            if (!m_visibleDepth)
                m_visibleDepth = std::make_unique<VisibleDepthPass>(m_gl);
            m_visibleRange = m_visibleDepth->ensure(*m_scene, m_sceneGeneration, fitCamera, size, &stats.visibleDepthDraws);
        }
        ShadowViewFrames views;
        FittedLight fitted;
        fitViews(settings, fitCamera, aspect, reversed, views, fitted);
        if (virtualMap) {
            // One view, the coarsest level's window over the whole scene: what the depth-map
            // view, the reach and the depth convention read; pages are its sub-squares.
            if (!m_virtual)
                m_virtual = std::make_unique<VirtualShadowMap>(m_gl);
            const VirtualLayout& layout = m_virtual->layout(settings, m_scene->bounds());
            views.set.views.resize(1);
            views.set.views.front().fit.volume = layout.coarsest;
            views.set.views.front().fit.anythingToShadow = true;
            views.frames.assign(1, computeLightFrame(settings.light, layout.coarsest, reversed));
            fitted.volume = layout.coarsest;
            fitted.anythingToShadow = true;
            fitted.texelAfter = layout.finestTexel;
        }
        m_views = std::move(views);
        m_fit = std::move(fitted);
        m_fitInputs = std::move(inputs);
        ++m_fitCount;
        // Where lookups can find a caster follows the fit, and so is kept with it.
        const int generation = m_reach.generation + 1;
        m_reach = settings.shadow.enabled ? reachOf(settings, camera) : ShadowReach{};
        m_reach.generation = generation;
    }
    const FittedLight& fit = m_fit;
    const ShadowViewFrames& views = m_views;
    const LightFrame& light = views.frames.front();
    stats.texelWorldSizeBeforeFit = fit.texelBefore;
    stats.texelWorldSize = fit.texelAfter;
    stats.lightFitted = fit.fitted;
    stats.reversedDepth = reversed;
    if (settings.shadow.enabled && usesLightWarp(settings)) {
        stats.warpViews = int(views.set.views.size());
        for (const ShadowView& view : views.set.views) {
            stats.warpedViews += view.fit.warped;
            if (stats.warpGain == 0.0)
                stats.warpGain = view.fit.warpGain;
            if (stats.warpDeclined == FrameStats::WarpDeclined::No && view.fit.warpSkip != FittedLight::WarpSkip::None)
                stats.warpDeclined = view.fit.warpSkip == FittedLight::WarpSkip::NoGain ? FrameStats::WarpDeclined::NoGain : FrameStats::WarpDeclined::AlongLight;
        }
    }

    if (virtualMap)
        renderPages(settings, storage, grid, size, timing, stats);
    else if (settings.shadow.enabled)
        renderViews(settings, storage, grid, timing, stats);
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
    m_light = light;
    m_viewSettings = settings;
}

ShadowReach Renderer::reachOf(const Settings& settings, const CameraFrame& camera) const
{
    const Scene& scene = m_scene->scene();
    std::vector<ReachObject> objects;
    objects.reserve(scene.objects.size());
    const bool culls = storageFor(settings).cullsFrontFaces(settings);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        ReachObject r{.bounds = m_scene->objectBounds(i), .casts = object.castsShadow, .receives = object.receivesShadow, .culledPlanePoint = {}, .culledPlaneNormal = {}};
        if (const std::optional<MeshPlane>& plane = m_scene->meshPlane(object.mesh); culls && plane) {
            // Through the model matrix by two edges, so a mirroring one turns the winding too.
            const glm::dvec3 u = glm::abs(plane->normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
            const glm::dvec3 e1 = glm::cross(plane->normal, u), e2 = glm::cross(plane->normal, e1);
            const auto world = [&](const glm::dvec3& p) { return glm::dvec3(object.model * glm::dvec4(p, 1.0)); };
            const glm::dvec3 origin = world(plane->point);
            const glm::dvec3 normal = glm::cross(world(plane->point + e1) - origin, world(plane->point + e2) - origin);
            if (glm::length(normal) > 0.0) {
                r.culledPlanePoint = origin;
                r.culledPlaneNormal = glm::normalize(normal);
            }
        }
        objects.push_back(r);
    }
    std::vector<ReachObject> receivers;
    for (const DrawItem& item : m_scene->drawItems())
        receivers.push_back({.bounds = item.bounds, .casts = item.castsShadow, .receives = item.receivesShadow, .culledPlanePoint = {}, .culledPlaneNormal = {}});
    return shadowlab::shadowReach(settings, m_views.frames, settings.map.size, objects, receivers, camera);
}

void Renderer::fitViews(const Settings& settings, const CameraFrame& fitCamera, double aspect, bool reversed, ShadowViewFrames& views,
                        FittedLight& fit) const
{
    const Scene& scene = m_scene->scene();
    // Receivers and casters as the scene's objects say.
    std::vector<FitObject> objects;
    objects.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        objects.push_back({m_scene->objectBounds(i), object.castsShadow, object.receivesShadow, scene.meshes.at(std::size_t(object.mesh)).convex});
    }
    views.camera = fitCamera;
    views.set = fitShadowViews(settings, objects, views.camera, aspect, m_visibleRange);
    fit = views.set.views.front().fit;
    // The fit the window and warnings show: the first view's volume, every view's cuts,
    // and something to shadow when any view has.
    for (std::size_t i = 1; i < views.set.views.size(); ++i) {
        const FittedLight& other = views.set.views[i].fit;
        fit.anythingToShadow = fit.anythingToShadow || other.anythingToShadow;
        fit.cutShare = std::max(fit.cutShare, other.cutShare);
        fit.cuts.insert(fit.cuts.end(), other.cuts.begin(), other.cuts.end());
    }
    for (const ShadowView& view : views.set.views)
        views.frames.push_back(computeLightFrame(settings.light, view.fit.volume, reversed));
}

ShadowStorage& Renderer::storageFor(const Settings& settings) const
{
    if (isMomentTechnique(settings.filter.mode)) {
        if (!m_momentsStorage)
            m_momentsStorage = makeMomentsStorage(m_gl);
        return *m_momentsStorage;
    }
    return *m_depthStorage;
}

void Renderer::renderViews(const Settings& settings, ShadowStorage& storage, ShadowTileGrid grid, TimingMode timing, FrameStats& stats)
{
    // What all views share: when it changes, every view is drawn or cleared again.
    const ShadowStorageKey shared = storage.key(settings, m_sceneGeneration, m_shadowMap.reversedDepth(), grid);
    const std::size_t count = m_views.set.views.size();
    bool fresh = false;
    if (m_shadowKey != shared || m_viewVolumes.size() != count) {
        m_viewVolumes.assign(count, std::nullopt);
        m_shadowKey = shared;
        fresh = true;
    }
    // Per view only for a light of several; one view's figures are the shadow pass's.
    const bool perView = count > 1;
    if (perView) {
        stats.viewRendered.assign(count, false);
        stats.viewDraws.assign(count, 0);
        stats.viewWallMs.assign(count, 0.0);
    }
    const int size = m_shadowMap.size();
    // Nothing to shadow: the tile reads lit, and stays so until the view has something.
    const auto wantedVolume = [this](std::size_t i) {
        const FittedLight& fit = m_views.set.views[i].fit;
        return fit.anythingToShadow ? std::optional<LightVolume>(fit.volume) : std::nullopt;
    };
    bool any = fresh, draws = false;
    for (std::size_t i = 0; i < count; ++i) {
        const std::optional<LightVolume> wanted = wantedVolume(i);
        const bool changed = fresh || m_viewVolumes[i] != wanted;
        any = any || changed;
        draws = draws || (changed && wanted);
    }
    if (!any)
        return;
    // Only a frame that draws a view is a shadow pass, timed; clearing a tile is not.
    if (draws)
        m_shadowTimer.begin();
    QElapsedTimer total;
    total.start();
    // A fresh map reads lit everywhere first, tiles no view uses included (3 cascades in 2 x 2).
    if (fresh && count < std::size_t(grid.columns * grid.rows))
        storage.clear(m_views.frames.front(), settings);
    for (std::size_t i = 0; i < count; ++i) {
        const ShadowView& view = m_views.set.views[i];
        const QRect tile(view.column * size, view.row * size, size, size);
        const std::optional<LightVolume> wanted = wantedVolume(i);
        if (!fresh && m_viewVolumes[i] == wanted)
            continue;
        QElapsedTimer wall;
        wall.start();
        int viewDraws = 0;
        if (wanted)
            viewDraws = storage.draw(*m_scene, m_views.frames[i], settings, tile, timing == TimingMode::Finish ? &stats.blurPassWallMs : nullptr);
        else
            storage.clear(m_views.frames[i], settings, tile);
        if (timing == TimingMode::Finish && perView) {
            m_gl->glFinish();
            stats.viewWallMs[i] = double(wall.nsecsElapsed()) * 1e-6;
        }
        if (perView) {
            stats.viewRendered[i] = true;
            stats.viewDraws[i] = viewDraws;
        }
        m_viewVolumes[i] = wanted;
        stats.shadowDraws += viewDraws;
    }
    ++m_mapGeneration;
    if (!draws)
        return;
    m_shadowTimer.end();
    stats.shadowPassRendered = true;
    ++m_shadowPassCount;
    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        stats.shadowPassWallMs = double(total.nsecsElapsed()) * 1e-6;
    }
}

void Renderer::renderPages(const Settings& settings, ShadowStorage& storage, ShadowTileGrid grid, QSize size, TimingMode timing, FrameStats& stats)
{
    ShadowStorageKey shared = storage.key(settings, m_sceneGeneration, m_shadowMap.reversedDepth(), grid);
    shared.mapSize = kVirtualSlotTexels;
    const bool invalidate = m_shadowKey != shared;
    m_shadowKey = shared;
    m_viewVolumes.clear();
    GLint previousDraw = 0, previousRead = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw);
    m_gl->glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    QElapsedTimer total;
    total.start();
    m_shadowTimer.begin();
    const auto frameOf = [&](const LightVolume& volume) { return computeLightFrame(settings.light, volume, m_shadowMap.reversedDepth()); };
    if (invalidate)
        storage.clear(m_views.frames.front(), settings);    // every slot reads lit until a page is drawn there
    int draws = 0;
    stats.virtualMap = true;
    stats.virtualPages = m_virtual->update(*m_scene, settings, m_camera, size, invalidate, storage, frameOf, &draws);
    m_shadowTimer.end();
    m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousDraw));
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    m_virtualUniforms = m_virtual->uniforms(m_camera);
    stats.shadowDraws = draws;
    if (stats.virtualPages.drawn == 0 && !invalidate)
        return;
    ++m_mapGeneration;
    stats.shadowPassRendered = stats.virtualPages.drawn > 0;
    m_shadowPassCount += stats.shadowPassRendered;
    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        stats.shadowPassWallMs = double(total.nsecsElapsed()) * 1e-6;
    }
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

void Renderer::drawLit(const Settings& settings, const RenderTarget& target, bool measure, FrameStats& stats)
{
    m_litTimer.begin();
    // Contact shadows march over the casters' depth as this camera sees them: part of the lit
    // pass's cost, drawn again only when the scene, the camera or the size changed.
    if (LitPass::usesContactShadows(settings)) {
        if (!m_cameraDepth)
            m_cameraDepth = std::make_unique<CameraDepthPass>(m_gl);
        stats.contactDepthDraws = m_cameraDepth->ensure(*m_scene, m_sceneGeneration, m_camera, target.size, settings.shadow.cutouts);
        m_litPass.setContactDepth(m_cameraDepth->texture());
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    } else {
        m_litPass.setContactDepth(0);
    }
    m_litPass.setShadowViews(&m_views);
    m_litPass.setVirtualMap(settings.shadow.enabled && settings.shadow.virtualMap ? &m_virtualUniforms : nullptr);
    m_litPass.setShadowReach(m_skipsOutOfReach ? &m_reach : nullptr);
    stats.litDraws = m_litPass.render(*m_scene, m_camera, m_light, settings, settings.shadow.enabled ? &m_shadowMap : nullptr, target, measure,
                                      m_depthRange.get(), storageFor(settings).momentsMap());
    stats.litPlainDraws = m_litPass.lastReachUse().plainDraws;
    stats.litReachMasked = m_litPass.lastReachUse().masked;
    m_litTimer.end();
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
    drawLit(settings, target, false, stats);
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
    drawLit(settings, target, true, stats);
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
    // What the technique stores: the moments for a moment technique, else the depth.
    if (const MomentsMap* moments = momentsShown()) {
        if (!m_depthView)
            m_depthView = std::make_unique<DepthViewPass>(m_gl);
        m_depthView->renderMoments(moments->texture(), m_viewSettings, target, visible, viewport);
        return;
    }
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
