#include "FrameUpdate.h"

#include "FramePlan.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace shadowlab {

namespace {

// Receivers and casters as the scene's objects say, moving ones where they go.
std::vector<FitObject> fitObjects(const Scene& scene, const SceneLayout& layout)
{
    std::vector<FitObject> objects;
    objects.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        objects.push_back({layout.fitBounds(i), object.castsShadow, object.receivesShadow, scene.meshes.at(std::size_t(object.mesh)).convex});
    }
    return objects;
}

} // namespace

ReachObject sceneCaster(const Scene& scene, const SceneLayout& layout, std::size_t i, bool cullsFrontFaces, bool floorsLeftOut)
{
    const SceneObject& object = scene.objects[i];
    const std::optional<WorldPlane> plane = layout.objectPlane(i);
    // A floor is left out of the map as a culled plane is: from its front side.
    return {.bounds = layout.objectBounds(i), .box = layout.objectBox(i), .casts = object.castsShadow, .receives = object.receivesShadow, .plane = plane,
            .frontFacesCulled = (cullsFrontFaces || (floorsLeftOut && layout.isFloor(i))) && plane};
}

std::vector<ReachObject> sceneCasters(const Scene& scene, const SceneLayout& layout, bool cullsFrontFaces, bool floorsLeftOut, CasterSet set)
{
    std::vector<ReachObject> casters;
    const std::vector<std::size_t>& moving = layout.movingObjects();
    if (set == CasterSet::Moving) {
        for (std::size_t i : moving)
            casters.push_back(sceneCaster(scene, layout, i, cullsFrontFaces, floorsLeftOut));
        return casters;
    }
    casters.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (set == CasterSet::Still && layout.moves(i))
            continue;
        casters.push_back(sceneCaster(scene, layout, i, cullsFrontFaces, floorsLeftOut));
    }
    return casters;
}

std::vector<ReachObject> sceneReceivers(const SceneLayout& layout)
{
    std::vector<ReachObject> receivers;
    for (const DrawItem& item : layout.drawItems()) {
        const std::optional<WorldPlane> plane = item.batch ? std::nullopt : layout.objectPlane(item.objects.front());
        const std::optional<std::array<glm::dvec3, 8>> box = item.batch ? std::nullopt : std::optional(layout.objectBox(item.objects.front()));
        receivers.push_back({.bounds = item.bounds, .box = box, .casts = item.castsShadow, .receives = item.receivesShadow, .plane = plane, .frontFacesCulled = false});
    }
    return receivers;
}

FrameUpdate::Frame FrameUpdate::begin(Inputs inputs, const Bounds& sceneBounds) const
{
    Frame frame;
    frame.aspect = double(inputs.size.width()) / double(inputs.size.height());
    frame.camera = computeCameraFrame(inputs.settings.camera, frame.aspect, sceneBounds);
    frame.refit = !m_inputs || !(*m_inputs == inputs);
    if (frame.refit && m_inputs) {
        Inputs posed = *m_inputs;
        posed.poseGeneration = inputs.poseGeneration;
        // sdsm splits the depth range the camera draws, which moving objects change.
        frame.reposeOnly = posed == inputs && !usesVisibleDepth(inputs.settings);
    }
    if (frame.refit)
        frame.fitCamera = inputs.fitCamera ? computeCameraFrame(*inputs.fitCamera, frame.aspect, sceneBounds) : frame.camera;
    frame.inputs = std::move(inputs);
    return frame;
}

void FrameUpdate::fit(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources)
{
    if (!frame.refit)
        return;
    const Settings& settings = frame.inputs.settings;
    if (frame.reposeOnly) {
        m_inputs = frame.inputs;
        findReach(frame, scene, layout, sources);
        return;
    }
    ShadowViewFrames views;
    views.camera = frame.fitCamera;
    views.set = fitShadowViews(settings, fitObjects(scene, layout), views.camera, frame.aspect, sources.visibleRange);
    FittedLight fitted = views.set.views.front().fit;
    // The fit the window and warnings show: the first view's volume, every view's cuts,
    // and something to shadow when any view has.
    for (std::size_t i = 1; i < views.set.views.size(); ++i) {
        const FittedLight& other = views.set.views[i].fit;
        fitted.anythingToShadow = fitted.anythingToShadow || other.anythingToShadow;
        fitted.cutShare = std::max(fitted.cutShare, other.cutShare);
        fitted.cuts.insert(fitted.cuts.end(), other.cuts.begin(), other.cuts.end());
    }
    for (const ShadowView& view : views.set.views)
        views.frames.push_back(computeLightFrame(settings.light, view.fit.volume, frame.inputs.reversed));
    if (const std::optional<VirtualLayout>& layoutOfPages = sources.virtualLayout) {
        // One view, the coarsest level's window over the whole scene: what the depth-map
        // view, the reach and the depth convention read; pages are its sub-squares.
        views.set.views.resize(1);
        views.set.views.front().fit.volume = layoutOfPages->coarsest;
        views.set.views.front().fit.anythingToShadow = true;
        views.frames.assign(1, computeLightFrame(settings.light, layoutOfPages->coarsest, frame.inputs.reversed));
        fitted.volume = layoutOfPages->coarsest;
        fitted.anythingToShadow = true;
        fitted.texelAfter = layoutOfPages->finestTexel;
    }
    m_views = std::move(views);
    m_fit = std::move(fitted);
    m_inputs = frame.inputs;
    ++m_fitCount;
    findReach(frame, scene, layout, sources);
}

void FrameUpdate::findReach(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources)
{
    // Where lookups can find a caster follows the fit and the casters, and so is kept with them.
    const Settings& settings = frame.inputs.settings;
    const int generation = m_reach.generation + 1;
    m_reach = ShadowReach{};
    m_casterTexels.clear();
    if (settings.shadow.enabled) {
        keepCasters(frame, scene, layout, sources);
        keepStillTexels(settings.map.size);
        for (std::size_t v = 0; v < m_views.frames.size(); ++v) {
            CasterTexels texels = m_stillTexels[v];
            if (!m_moving.empty())
                texels.add(shadowlab::casterTexels(m_views.frames[v], settings.map.size, m_moving));
            m_casterTexels.push_back(texels);
        }
        // The reach is the software profile's (RasteriserTuning::skipsOutOfReach): found over
        // every caster and receiver only where it is used.
        if (sources.reach) {
            keepReachBoxes(settings, scene, layout);
            m_reach = shadowReach(m_views.frames, m_reachBoxes, sceneReceivers(layout), frame.camera);
        }
    }
    m_reach.generation = generation;
}

void FrameUpdate::keepCasters(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources)
{
    // The casters follow the scene, the storage's culling and, for the moving ones, where they
    // are: a camera walk keeps them all, a frame of moving casters finds only theirs.
    const CastersKey still{frame.inputs.sceneGeneration, -1, sources.cullsFrontFaces, sources.floorsLeftOut};
    CastersKey moving = still;
    moving.poseGeneration = frame.inputs.poseGeneration;
    if (still != m_stillKey)
        m_still = sceneCasters(scene, layout, sources.cullsFrontFaces, sources.floorsLeftOut, CasterSet::Still);
    if (moving != m_movingKey)
        m_moving = sceneCasters(scene, layout, sources.cullsFrontFaces, sources.floorsLeftOut, CasterSet::Moving);
    m_stillKey = still;
    m_movingKey = moving;
}

void FrameUpdate::keepStillTexels(int mapSize)
{
    // They stand while only moving casters move (a frame of moving casters costs what they do,
    // whatever the size of the still scene), and while a camera's move leaves the views as they
    // were (a stabilised fit moves them by whole steps).
    StillTexelsKey key{*m_stillKey, mapSize, m_views.frames};
    if (key == m_stillTexelsKey)
        return;
    m_stillTexels.clear();
    for (const LightFrame& view : m_views.frames)
        m_stillTexels.push_back(shadowlab::casterTexels(view, mapSize, m_still));
    m_stillTexelsKey = std::move(key);
}

void FrameUpdate::keepReachBoxes(const Settings& settings, const Scene& scene, const SceneLayout& layout)
{
    // The boxes follow the views and the casters, not the camera: a camera walk under a
    // stabilised fit finds only where the receivers lie against them.
    ReachBoxesFor key{*m_movingKey, settings.map.size, m_views.frames, reachBoxesKey(settings)};
    if (key == m_reachBoxesFor)
        return;
    // Every caster in the scene's order, as sceneCasters lists them.
    std::vector<ReachObject> casters;
    casters.reserve(scene.objects.size());
    std::size_t still = 0, moving = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        casters.push_back(layout.moves(i) ? m_moving.at(moving++) : m_still.at(still++));
    m_reachBoxes = reachBoxes(settings, m_views.frames, settings.map.size, casters);
    m_reachBoxesFor = std::move(key);
}

void FrameUpdate::describe(const FramePlan& plan, FrameStats& stats) const
{
    stats.texelWorldSizeBeforeFit = m_fit.texelBefore;
    stats.texelWorldSize = m_fit.texelAfter;
    stats.lightFitted = m_fit.fitted;
    if (!plan.shadows || !plan.lightWarp)
        return;
    stats.warpViews = int(m_views.set.views.size());
    for (const ShadowView& view : m_views.set.views) {
        stats.warpedViews += view.fit.warped;
        if (stats.warpGain == 0.0)
            stats.warpGain = view.fit.warpGain;
        if (stats.warpDeclined == FrameStats::WarpDeclined::No && view.fit.warpSkip != FittedLight::WarpSkip::None)
            stats.warpDeclined = view.fit.warpSkip == FittedLight::WarpSkip::NoGain ? FrameStats::WarpDeclined::NoGain : FrameStats::WarpDeclined::AlongLight;
    }
}

} // namespace shadowlab
