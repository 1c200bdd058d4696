#include "Renderer.h"

#include <QElapsedTimer>

#include <algorithm>
#include <utility>

// The renderer's shadow pass: the views of a light (one map, cascades, cube faces) each in its
// tile, drawn where shadow.cache says, and a virtual map's pages. The rest of the frame is in
// Renderer.cpp.
namespace shadowlab {

namespace {

// Rectangles of a view's own square moved into its tile of the map.
std::vector<QRect> inTile(std::vector<QRect> rects, const QRect& tile)
{
    for (QRect& rect : rects)
        rect.translate(tile.topLeft());
    return rects;
}

} // namespace

int Renderer::keyGeneration(const FramePlan& plan) const
{
    // A cache keeps what does not move through a caster's move; without one, it draws again.
    return plan.cache == ShadowCachePolicy::Off ? m_sceneGeneration : m_shapeGeneration;
}

bool Renderer::beginViews(const FramePlan& plan, const ShadowStorage& storage, bool castersMoved, ViewCause& cause)
{
    // What all views share: when it changes, every view is drawn or cleared again.
    const ShadowStorageKey shared = storage.key(plan, keyGeneration(plan));
    if (m_shadowKey == shared) {
        // shadow.force_invalidate: as if the light moved.
        if (!plan.settings.shadow.forceInvalidate)
            return false;
        cause = ViewCause::Light;
        m_viewCache.reset();
        return true;
    }
    // New settings start a new cycle of slices (map.slices): what a setting draws does not
    // depend on the draws before it. A moving light or camera keeps the key, and the cycle,
    // and so does invalidateShadowMap(), which stands for one.
    if (m_shadowKey && *m_shadowKey != shared)
        m_shadowMap.depthSlices().restart();
    // Without a cache, a caster's move alone draws every view: for it.
    std::optional<ShadowStorageKey> posed = m_shadowKey;
    if (posed)
        posed->sceneGeneration = shared.sceneGeneration;
    cause = castersMoved && posed == shared ? ViewCause::Casters : ViewCause::New;
    m_viewCache.reset();
    m_shadowKey = shared;
    return true;
}

std::vector<std::vector<QRect>> Renderer::movingTexels(int mapSize) const
{
    // Where each moving caster lies in each view now (where they were, the cache remembers).
    const std::vector<LightFrame>& frames = m_update.views().frames;
    std::vector<std::vector<QRect>> texels(frames.size());
    for (const DrawItem& item : m_scene->drawItems()) {
        if (!item.moves || !item.castsShadow)
            continue;
        const std::vector<ReachObject> one{{.bounds = item.bounds, .box = std::nullopt, .casts = true, .receives = item.receivesShadow, .plane = std::nullopt}};
        for (std::size_t i = 0; i < frames.size(); ++i) {
            if (const QRect rect = casterTexels(frames[i], mapSize, one).drawn; !rect.isEmpty())
                texels[i].push_back(rect);
        }
    }
    return texels;
}

std::vector<QRect> Renderer::readTexels(const Settings& settings) const
{
    // Where the frame's pixels may read each view: a moving caster elsewhere changes none of them.
    Bounds receivers;
    for (const DrawItem& item : m_scene->drawItems()) {
        if (item.receivesShadow)
            receivers.extend(item.bounds);
    }
    std::vector<QRect> read;
    for (const LightFrame& frame : m_update.views().frames) {
        const std::optional<double> margin = lookupReachTexels(settings, frame);
        if (!margin)
            return {};      // a lookup may read anywhere: every view is read everywhere
        read.push_back(shadowlab::readTexels(frame, m_shadowMap.size(), m_camera, receivers, *margin));
    }
    return read;
}

std::vector<std::optional<LightVolume>> Renderer::wantedVolumes() const
{
    // Nothing to shadow, or no caster in the view: the tile reads lit, and stays so until the
    // view has something.
    const std::vector<CasterTexels>& texels = m_update.casterTexels();
    std::vector<std::optional<LightVolume>> wanted;
    for (std::size_t i = 0; i < m_update.views().set.views.size(); ++i) {
        const FittedLight& fit = m_update.views().set.views[i].fit;
        const bool casters = i >= texels.size() || !texels[i].drawn.isEmpty();
        wanted.push_back(fit.anythingToShadow && casters ? std::optional<LightVolume>(fit.volume) : std::nullopt);
    }
    return wanted;
}

double Renderer::casterCoverage(std::size_t count) const
{
    // How much of a one-view map its casters may cover (DepthSlices::setCasterCoverage). A map of
    // several tiles clears each under a scissor, which a rasteriser runs as a draw over the
    // cleared texels, as dear as a slice's reads of them: it slices whatever its casters cover.
    if (count > 1)
        return 0.0;
    double coverage = 0.0;
    for (const ReachBox& box : m_update.reach().boxes) {
        const glm::dvec2 size = glm::clamp(box.uvMax, 0.0, 1.0) - glm::clamp(box.uvMin, 0.0, 1.0);
        coverage += std::max(size.x, 0.0) * std::max(size.y, 0.0);
    }
    return std::min(coverage, 1.0);
}

bool Renderer::slicesViews(const FramePlan& plan, std::vector<ShadowCache::Decision>& decisions, const std::vector<std::optional<LightVolume>>& wanted) const
{
    const auto drawn = [](const ShadowCache::Decision& d) { return d.work == ShadowCache::Work::Draw; };
    if (decisions.size() < 2 || std::none_of(decisions.begin(), decisions.end(), drawn))
        return false;
    bool sliced = plan.slices > 1 && !plan.moments && ShadowMap::slices(plan.slices, plan.settings.map.format, plan.reversedDepth);
    // A perspective view's depth steps widen with distance: a slice keeps log2(n) bits fewer of
    // the 24, so where a view with casters would then have steps at its far plane wider than an
    // eighth of a texel there (far / near beyond 512 at 2048² and 4 slices), the pass clears.
    const double step = double(plan.slices) / double(1 << 24);
    const std::vector<LightFrame>& frames = m_update.views().frames;
    for (std::size_t i = 0; i < frames.size() && i < wanted.size(); ++i) {
        const LightVolume& v = frames[i].volume;
        if (wanted[i] && v.perspective && step * (v.farPlane - v.nearPlane) / v.nearPlane > texelWorldSize(v, m_shadowMap.size()) / 8.0)
            sliced = false;
    }
    // A pass that draws moves the whole map to another slice (or out of slices), where what a
    // kept view holds would read as empty: every view with casters is drawn then. Without a
    // cache, which core's slicesDepth requires, every pass that draws is fresh and draws them
    // all already; this holds it whatever decides.
    if (sliced || m_shadowMap.slice().scale < 1.0) {
        for (std::size_t i = 0; i < decisions.size() && i < wanted.size(); ++i) {
            if (decisions[i].work == ShadowCache::Work::Keep && wanted[i])
                decisions[i].work = ShadowCache::Work::Draw;
        }
    }
    return sliced;
}

void Renderer::renderViews(const FramePlan& plan, ShadowStorage& storage, bool castersMoved, TimingMode timing, FrameStats& stats)
{
    const std::size_t count = m_update.views().set.views.size();
    ShadowCache::Frame frame;
    frame.policy = plan.cache;
    frame.interval = plan.settings.shadow.cacheInterval;
    frame.fresh = beginViews(plan, storage, castersMoved, frame.freshCause);
    // Another count of views (4 cascades to 3) in the same tiles is new too.
    if (m_viewCache.viewCount() != count && !frame.fresh) {
        frame.fresh = true;
        frame.freshCause = ViewCause::New;
    }
    frame.castersMoved = castersMoved;
    frame.requested = std::exchange(m_redrawRequested, false);
    frame.wanted = wantedVolumes();
    if (keepsViews(plan.cache)) {
        frame.movingTexels = movingTexels(m_shadowMap.size());
        frame.readTexels = readTexels(plan.settings);
    }
    std::vector<ShadowCache::Decision> decisions = m_viewCache.decide(frame);
    const bool sliced = slicesViews(plan, decisions, frame.wanted);
    bool any = false, draws = false;
    for (const ShadowCache::Decision& d : decisions) {
        if (plan.cache != ShadowCachePolicy::Off)
            stats.viewCauses.push_back(d.cause);
        any = any || d.work != ShadowCache::Work::Keep;
        draws = draws || (d.work != ShadowCache::Work::Keep && d.work != ShadowCache::Work::Clear);
    }
    stats.cacheBytes = storage.cacheBytes();
    if (!any)
        return;
    // Per view only for a light of several; one view's figures are the shadow pass's.
    const bool perView = count > 1;
    if (perView) {
        stats.viewRendered.assign(count, false);
        stats.viewDraws.assign(count, 0);
        stats.viewWallMs.assign(count, 0.0);
    }
    const int clearsBefore = m_shadowMap.clearCount();
    m_shadowMap.depthSlices().setCasterCoverage(casterCoverage(count), plan.settings.map.sliceCoverage);
    // Only a frame that draws a view is a shadow pass, timed; clearing a tile is not.
    if (draws)
        m_shadowTimer.begin();
    QElapsedTimer total;
    total.start();
    // A fresh map reads lit everywhere first, tiles no view uses included (3 cascades in 2 x 2).
    if (frame.fresh && count < std::size_t(plan.grid.columns * plan.grid.rows))
        storage.clear(m_update.views().frames.front(), plan);
    if (draws)
        m_shadowMap.beginPass(sliced ? plan.slices : 1);
    for (std::size_t i = 0; i < count; ++i) {
        if (decisions[i].work != ShadowCache::Work::Keep)
            drawView(i, decisions[i], frame.wanted[i], i < frame.movingTexels.size() ? frame.movingTexels[i] : std::vector<QRect>(), plan, storage, timing,
                     stats);
    }
    ++m_mapGeneration;
    if (!draws)
        return;
    m_shadowTimer.end();
    stats.shadowPassRendered = true;
    // A moments map is cleared with each view drawn; the depth map as DepthSlices::beginDraw says.
    stats.shadowMapCleared = storage.momentsMap() != nullptr || m_shadowMap.clearCount() != clearsBefore;
    ++m_shadowPassCount;
    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        stats.shadowPassWallMs = double(total.nsecsElapsed()) * 1e-6;
    }
}

void Renderer::drawView(std::size_t i, const ShadowCache::Decision& decision, const std::optional<LightVolume>& wanted, const std::vector<QRect>& movingNow,
                        const FramePlan& plan, ShadowStorage& storage, TimingMode timing, FrameStats& stats)
{
    const ShadowView& view = m_update.views().set.views[i];
    const int size = m_shadowMap.size();
    const QRect tile(view.column * size, view.row * size, size, size);
    const std::vector<CasterTexels>& texels = m_update.casterTexels();
    const CasterTexels* casters = i < texels.size() ? &texels[i] : nullptr;
    const LightFrame& light = m_update.views().frames[i];
    double* blurMs = timing == TimingMode::Finish ? &stats.blurPassWallMs : nullptr;
    const bool perView = m_update.views().set.views.size() > 1;
    QElapsedTimer wall;
    wall.start();
    int draws = 0;
    std::vector<QRect> moving;
    using Work = ShadowCache::Work;
    if (decision.work == Work::Draw) {
        draws = storage.draw(*m_scene, light, plan, tile, casters, blurMs);
    } else if (decision.work == Work::Refresh || decision.work == Work::Restore) {
        const ShadowStorage::CachedDraw drawn = storage.drawCached(
            *m_scene, light, plan, tile, casters, blurMs,
            decision.work == Work::Refresh ? ShadowStorage::CacheStep::Refresh : ShadowStorage::CacheStep::Restore,
            inTile(decision.areas, tile));
        draws = drawn.draws;
        if (drawn.movingDraws > 0)
            moving = movingNow;
    } else {
        storage.clear(light, plan, tile);
    }
    if (timing == TimingMode::Finish && perView) {
        m_gl->glFinish();
        stats.viewWallMs[i] = double(wall.nsecsElapsed()) * 1e-6;
    }
    if (perView) {
        // A view without casters is cleared where it was written, not drawn.
        stats.viewRendered[i] = decision.work != Work::Clear;
        stats.viewDraws[i] = draws;
    }
    m_viewCache.done(i, decision, wanted, moving);
    stats.shadowDraws += draws;
}

void Renderer::setVirtualAsyncRequests(bool async)
{
    m_virtualAsync = async;
    if (m_virtual)
        m_virtual->setAsyncRequests(async);
}

void Renderer::renderPages(const FramePlan& plan, ShadowStorage& storage, QSize size, TimingMode timing, FrameStats& stats)
{
    const Settings& settings = plan.settings;
    const ShadowStorageKey shared = storage.key(plan, keyGeneration(plan));
    const bool invalidate = m_shadowKey != shared || plan.settings.shadow.forceInvalidate;
    m_shadowKey = shared;
    m_viewCache.reset();
    GLint previousDraw = 0, previousRead = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw);
    m_gl->glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    QElapsedTimer total;
    total.start();
    m_shadowTimer.begin();
    const auto frameOf = [&](const LightVolume& volume) { return computeLightFrame(settings.light, volume, m_shadowMap.reversedDepth()); };
    if (invalidate)
        storage.clear(m_update.views().frames.front(), plan);    // every slot reads lit until a page is drawn there
    m_shadowMap.beginPass(1);   // a page's slot is cleared as it is drawn: no slices
    int draws = 0;
    stats.virtualMap = true;
    std::vector<Bounds> castersMoved;
    if (m_castersMoved) {
        // Under shadow.cache=pages only the pixels where moving objects were and are ask again.
        std::optional<std::vector<QRect>> within;
        if (plan.cache == ShadowCachePolicy::Pages && !m_movedBounds.empty())
            within.emplace();
        for (const MovingBounds& moved : m_movedBounds) {
            if (moved.casts)
                castersMoved.push_back(moved.bounds);
            const std::optional<QRect> pixels = within ? windowPixels(moved.bounds, m_camera.viewProjection, size) : std::nullopt;
            if (!pixels)
                within.reset();
            else if (!pixels->isEmpty())
                within->push_back(*pixels);
        }
        m_virtual->askAgain(within);
    }
    stats.virtualPages = m_virtual->update(*m_scene, plan, m_camera, size, invalidate, storage, frameOf, &draws);
    if (plan.cache == ShadowCachePolicy::Pages) {
        stats.virtualPages.invalidated = m_virtual->redrawTouched(*m_scene, plan, castersMoved, storage, frameOf, &draws, stats.pageCauses);
        stats.virtualPages.drawn += stats.virtualPages.invalidated;
        stats.virtualPages.resident = m_virtual->cache().resident();
    }
    m_shadowTimer.end();
    m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousDraw));
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    m_virtualUniforms = m_virtual->uniforms(m_camera);
    stats.shadowDraws = draws;
    // As rendered: the finest level the frame's pixels read, not the layout's level 0.
    if (stats.virtualPages.finestLevel >= 0)
        stats.texelWorldSize = m_virtual->currentLayout()->texel(stats.virtualPages.finestLevel);
    if (stats.virtualPages.drawn == 0 && !invalidate)
        return;
    ++m_mapGeneration;
    stats.shadowPassRendered = stats.virtualPages.drawn > 0;
    stats.shadowMapCleared = stats.shadowPassRendered;     // each page is cleared where it is drawn
    m_shadowPassCount += stats.shadowPassRendered;
    if (timing == TimingMode::Finish) {
        m_gl->glFinish();
        stats.shadowPassWallMs = double(total.nsecsElapsed()) * 1e-6;
    }
}

} // namespace shadowlab
