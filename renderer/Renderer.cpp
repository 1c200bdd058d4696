#include "Renderer.h"

#include "LightFitting.h"
#include "RenderError.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsError.h"

#include <algorithm>
#include <utility>

#include <QElapsedTimer>

namespace shadowlab {

Renderer::Renderer(GlFunctions* gl)
    : m_gl(gl), m_shadowMap(gl), m_depthPass(gl), m_depthStorage(makeDepthStorage(gl, m_shadowMap, m_depthPass)), m_litPass(gl),
      m_shadowTimer(gl), m_litTimer(gl), m_shadowPrimitives(gl, GL_PRIMITIVES_GENERATED), m_shadowSamples(gl, GL_SAMPLES_PASSED),
      m_litPrimitives(gl, GL_PRIMITIVES_GENERATED)
{
    m_softwareDriver = isSoftwareRenderer(rendererString());
    // A software rasteriser's timer queries measure nothing (its rasterisation is deferred past
    // them) and cost the pass after a shadow pass a sixth of its time: wall times stand there.
    const bool gpuTimed = !m_softwareDriver;
    m_shadowTimer.setEnabled(gpuTimed);
    m_litTimer.setEnabled(gpuTimed);
}

const MomentsMap* Renderer::momentsMap() const
{
    return m_momentsStorage ? m_momentsStorage->momentsMap() : nullptr;
}

const MomentsMap* Renderer::momentsShown() const
{
    return m_plan.shadows && m_plan.moments ? momentsMap() : nullptr;
}

Renderer::~Renderer() = default;

void Renderer::setScene(std::optional<Scene> scene)
{
    m_customScene = std::move(scene);
    m_sceneChanged = true;
}

void Renderer::setSceneFile(const QString& path, std::shared_ptr<const Scene> scene)
{
    // A new load of the file drawn now (it changed on disk) is drawn from the next frame.
    m_sceneChanged = m_sceneChanged || (m_drawnFile && m_drawnFile->first == path && m_drawnFile->second != scene);
    m_sceneFile = {path, std::move(scene)};
}

const Renderer::SceneFile* Renderer::fileFor(const QString& path) const
{
    if (m_sceneFile && m_sceneFile->first == path)
        return &*m_sceneFile;
    return m_drawnFile && m_drawnFile->first == path ? &*m_drawnFile : nullptr;
}

bool Renderer::holdsOlderSceneFile(const QString& path, const std::shared_ptr<const Scene>& latest) const
{
    const SceneFile* file = m_customScene ? nullptr : fileFor(path);
    return file != nullptr && file->second != latest;
}

bool Renderer::needsSceneFile(const Settings& settings) const
{
    // The file drawn now needs nothing either: going back to it after another file's frame
    // failed draws what is uploaded, without reading the file again.
    return !m_customScene && !isPresetName(settings.scene) && !fileFor(settings.scene);
}

void Renderer::prepareFrame(const Settings& settings, QSize size, TimingMode timing, FrameStats& stats, bool measure)
{
    ensureValid(settings);
    // Compute everything that can fail before touching state, so a bad value keeps the last frame.
    computeLightFrame(settings.light);
    FramePlan plan = planFrame(settings, m_softwareDriver, m_depthPass.supportsReversedDepth());
    warnOnce(plan);
    if (plan.virtualMap && plan.grid.columns * plan.tileSize > maxTextureSize())
        throw SettingsError(QStringLiteral("shadow.virtual_pool"),
                            QStringLiteral("a pool of %1² pages needs a %2² texture, and this driver allows %3² at most; lower shadow.virtual_pool")
                                .arg(plan.grid.columns).arg(plan.grid.columns * plan.tileSize).arg(maxTextureSize()));
    ShadowStorage& storage = storageFor(plan);
    ensureMap(plan, storage);
    const int sceneBefore = m_sceneGeneration;
    ensureScene(settings);
    const bool newScene = m_sceneGeneration != sceneBefore;
    // Moving objects to where they are at the frame's time: everything that depends on where the
    // casters are is due again, as for a new scene (its geometry stays uploaded). A move no
    // shadow pass has seen (shadows off, a frame that failed) stays due until one does.
    // (Collected with shadows off too: the pages wait for them.)
    const bool pages = settings.shadow.virtualMap && settings.shadow.cache == ShadowCachePolicy::Pages;
    const std::vector<MovingBounds> before = pages ? movingBounds() : std::vector<MovingBounds>();
    const bool casterMoved = m_scene->pose(settings.animation.time);
    if (casterMoved) {
        ++m_sceneGeneration;
        m_castersMoved = true;
        // shadow.cache=pages draws again the pages where a moving caster was and where it is,
        // and asks again for the pages of the pixels where a moving object was and is.
        if (!before.empty()) {
            const std::vector<MovingBounds> after = movingBounds();
            m_movedBounds.resize(after.size());
            for (std::size_t k = 0; k < after.size(); ++k) {
                m_movedBounds[k].bounds.extend(before.at(k).bounds);
                m_movedBounds[k].bounds.extend(after[k].bounds);
                m_movedBounds[k].casts = after[k].casts;
            }
        }
    }

    // Update: the cameras, and the fit when one of its inputs changed (the clock through the
    // scene's generation: a still scene's time changes nothing).
    Settings fitted = settings;
    fitted.animation = {};
    const FrameUpdate::Frame frame =
        m_update.begin({m_shapeGeneration, m_sceneGeneration, std::move(fitted), m_fitCamera, size, plan.reversedDepth}, m_scene->bounds());
    m_camera = frame.camera;
    if (frame.refit)
        refit(frame, plan, storage, stats);
    m_update.describe(plan, stats);
    stats.reversedDepth = plan.reversedDepth;
    stats.softwareProfile = plan.tuning.software;

    // A map in a later slice than its first differs from a cleared one by a 24-bit step at
    // exact ties (a bias of 0): a measurement draws it again after a clear, so the same settings
    // measure the same whatever was drawn before.
    if (measure) {
        if (m_shadowMap.depthSlices().index() > 0)
            invalidateShadowMap();
        m_shadowMap.depthSlices().restart();    // a draw this frame, for whatever reason, clears first
    }
    // Render: the shadow pass where its inputs changed, then what it feeds.
    storage.takeCounts();   // what a pass did before this frame is not its
    {
        CountingScope counting(m_counting, {&m_shadowPrimitives, &m_shadowSamples});
        if (plan.virtualMap)
            renderPages(plan, storage, size, timing, stats);
        else if (plan.shadows)
            renderViews(plan, storage, m_castersMoved, timing, stats);
        if (plan.shadows) {
            m_castersMoved = false;
            m_movedBounds.clear();
        }
    }
    countShadowPass(plan, storage, stats);
    buildDepthRange(plan, timing, stats);
    m_light = m_update.views().frames.front();
    stats.redraw = redrawReason(stats.shadowPassRendered, casterMoved, newScene, settings);
    m_plan = std::move(plan);
}

std::vector<Renderer::MovingBounds> Renderer::movingBounds() const
{
    std::vector<MovingBounds> bounds;
    for (const DrawItem& item : m_scene->drawItems()) {
        if (item.moves)
            bounds.push_back({item.bounds, item.castsShadow});
    }
    return bounds;
}

FrameStats::Redraw Renderer::redrawReason(bool drawn, bool casterMoved, bool sceneChanged, const Settings& settings) const
{
    using Redraw = FrameStats::Redraw;
    if (!drawn)
        return Redraw::None;
    if (sceneChanged)
        return Redraw::Scene;
    if (casterMoved)
        return Redraw::Casters;
    if (settings.light != m_plan.settings.light)
        return Redraw::Light;
    if (settings.camera != m_plan.settings.camera)
        return Redraw::Camera;
    return Redraw::Settings;
}

void Renderer::warnOnce(const FramePlan& plan)
{
    if (plan.reversedDepthWanted && !plan.reversedDepth && !m_warnedNoReversedDepth) {
        qWarning("shadowlab: this driver has neither OpenGL 4.5 nor GL_ARB_clip_control; depth32f maps use conventional depth");
        m_warnedNoReversedDepth = true;
    }
}

void Renderer::ensureMap(const FramePlan& plan, ShadowStorage& storage)
{
    if (!plan.shadows)
        return;
    m_shadowMap.ensureTiles(plan.tileSize, plan.grid.columns, plan.grid.rows, plan.settings.map.format, plan.reversedDepth);
    storage.ensure(plan);
}

Scene Renderer::sceneOf(const Settings& settings) const
{
    if (m_customScene)
        return *m_customScene;
    if (isPresetName(settings.scene))
        return buildPresetScene(settings.scene);
    const SceneFile* file = fileFor(settings.scene);
    if (!file)
        throw RenderError(QStringLiteral("the scene file '%1' was not loaded before the frame (Renderer::setSceneFile)").arg(settings.scene));
    return *file->second;
}

void Renderer::ensureScene(const Settings& settings)
{
    if (m_sceneChanged || !m_scene || (!m_customScene && m_scene->scene().name != settings.scene) || m_objectSwitches != settings.objects) {
        Scene scene = sceneOf(settings);
        applyObjectSwitches(scene, settings.objects);    // throws for an object the scene has not: the last scene stays
        const SceneFile* file = m_customScene ? nullptr : fileFor(settings.scene);
        std::optional<SceneFile> drawn = file ? std::optional<SceneFile>(*file) : std::nullopt;
        m_scene = std::make_unique<GpuScene>(m_gl, std::move(scene));
        m_drawnFile = std::move(drawn);
        m_objectSwitches = settings.objects;
        m_sceneChanged = false;
        ++m_sceneGeneration;
        ++m_shapeGeneration;
    }
}

void Renderer::refit(const FrameUpdate::Frame& frame, const FramePlan& plan, const ShadowStorage& storage, FrameStats& stats)
{
    const Settings& settings = frame.inputs.settings;
    FrameUpdate::FitSources sources;
    // Sample-distribution cascades split the depth range the fitting camera draws.
    m_visibleRange.reset();
    if (plan.visibleDepth) {
        if (!m_visibleDepth)
            m_visibleDepth = std::make_unique<VisibleDepthPass>(m_gl);
        m_visibleRange = m_visibleDepth->ensure(*m_scene, m_sceneGeneration, frame.fitCamera, frame.inputs.size, &stats.visibleDepthDraws);
    }
    sources.visibleRange = m_visibleRange;
    if (plan.virtualMap) {
        if (!m_virtual) {
            m_virtual = std::make_unique<VirtualShadowMap>(m_gl);
            m_virtual->setAsyncRequests(m_virtualAsync);
        }
        m_virtual->setReduction(plan.tuning.cpuVirtualRequests ? VirtualShadowMap::Reduction::Cpu : VirtualShadowMap::Reduction::Gpu);
        sources.virtualLayout = m_virtual->layout(settings, m_scene->bounds());
    }
    sources.cullsFrontFaces = storage.cullsFrontFaces(plan);
    sources.reach = plan.tuning.skipsOutOfReach || plan.tuning.depthSlices;
    sources.floorsLeftOut = storage.leavesOutFloors(plan);
    m_update.fit(frame, m_scene->scene(), m_scene->layout(), sources);
}

void Renderer::buildDepthRange(const FramePlan& plan, TimingMode timing, FrameStats& stats)
{
    // The min/max depth mip follows the map: built after a shadow pass, or when penumbra-only
    // filtering or a blocker search is turned on over a map it was not built from.
    if (!plan.depthRange || m_depthRangeGeneration == m_mapGeneration)
        return;
    if (!m_depthRange)
        m_depthRange = std::make_unique<DepthRangePass>(m_gl);
    QElapsedTimer wall;
    wall.start();
    // Under the software profile only where the map's passes wrote since its tiles' clears (a
    // cleared texel reads as the far plane in every slice, as the texels earlier slices left
    // do); a virtual map's pool, written page by page, whole.
    if (plan.tuning.rangesWrittenTexels && !plan.virtualMap)
        m_depthRange->build(m_shadowMap, false, &m_shadowMap.written().writtenTiles());
    else
        m_depthRange->build(m_shadowMap);
    m_depthRangeGeneration = m_mapGeneration;
    if (timing == TimingMode::Finish && stats.shadowPassRendered) {
        m_gl->glFinish();
        stats.shadowPassWallMs += double(wall.nsecsElapsed()) * 1e-6;
    }
}

ShadowStorage& Renderer::storageFor(const FramePlan& plan)
{
    if (plan.moments) {
        if (!m_momentsStorage)
            m_momentsStorage = makeMomentsStorage(m_gl);
        return *m_momentsStorage;
    }
    return *m_depthStorage;
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

void Renderer::countShadowPass(const FramePlan& plan, ShadowStorage& storage, FrameStats& stats)
{
    FrameCounts& counts = stats.counts;
    const ShadowStorage::Counts done = storage.takeCounts();
    counts.shadow.draws = stats.shadowDraws;
    counts.clearedTexels = done.clearedTexels;
    counts.blurTexels = done.blurTexels;
    counts.blurBytes = done.blurBytes;
    counts.copiedTexels = done.copiedTexels;
    counts.cacheBytes = storage.cacheBytes();
    counts.mapBytes = !plan.shadows ? 0
        : plan.virtualMap && m_virtual ? std::int64_t(m_shadowMap.width()) * m_shadowMap.height() * 4 + m_virtual->pageTableBytes()
                                       : storage.bytes();
    counts.tapsPerLookup = plan.tapsPerLookup;
    if (m_counting) {
        counts.shadow.primitives = m_shadowPrimitives.result();
        counts.shadow.samples = m_shadowSamples.result();
    }
}

void Renderer::drawLit(const FramePlan& plan, const RenderTarget& target, bool measure, FrameStats& stats)
{
    CountingScope counting(m_counting, {&m_litPrimitives});
    m_litPass.setCounting(m_counting);
    m_litTimer.begin();
    // Contact shadows march over the casters' depth as this camera sees them: part of the lit
    // pass's cost, drawn again only when the scene, the camera or the size changed.
    if (plan.contactShadows) {
        if (!m_cameraDepth)
            m_cameraDepth = std::make_unique<CameraDepthPass>(m_gl);
        stats.contactDepthDraws = m_cameraDepth->ensure(*m_scene, m_sceneGeneration, m_camera, target.size, plan.settings.shadow.cutouts);
        m_litPass.setContactDepth(m_cameraDepth->texture());
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    } else {
        m_litPass.setContactDepth(0);
    }
    m_litPass.setShadowViews(&m_update.views());
    m_litPass.setVirtualMap(plan.virtualMap ? &m_virtualUniforms : nullptr);
    m_litPass.setShadowReach(plan.tuning.skipsOutOfReach ? &m_update.reach() : nullptr);
    stats.litDraws = m_litPass.render(*m_scene, m_camera, m_light, plan, plan.shadows ? &m_shadowMap : nullptr, target, measure, m_depthRange.get(),
                                      plan.moments ? momentsMap() : nullptr);
    stats.litPlainDraws = m_litPass.lastReachUse().plainDraws;
    stats.litReachMasked = m_litPass.lastReachUse().masked;
    m_litTimer.end();
    stats.counts.lit.draws = stats.litDraws;
    if (m_counting) {
        counting.end();
        stats.counts.lit.primitives = m_litPrimitives.result();
        const LitPass::Fragments fragments = m_litPass.lastFragments();
        stats.counts.lit.samples = fragments.lookup + fragments.plain;
        stats.counts.lookupFragments = plan.shadows ? fragments.lookup : 0;
    }
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
    drawLit(m_plan, target, false, stats);
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
    prepareFrame(settings, size, TimingMode::Finish, stats, true);
    if (!m_measureTarget)
        m_measureTarget = std::make_unique<MeasureTarget>(m_gl);
    const RenderTarget target = m_measureTarget->ensure(size);
    drawLit(m_plan, target, true, stats);
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
        m_depthView->renderMoments(moments->texture(), m_plan.settings, target, visible, viewport);
        return;
    }
    const std::optional<DepthSpan> span = depthMapSpan();
    m_depthView->render(m_shadowMap, m_light, target, visible, viewport, span);
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
