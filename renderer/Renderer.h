#pragma once

#include "CameraDepthPass.h"
#include "CountQuery.h"
#include "VisibleDepthPass.h"
#include "DepthPass.h"
#include "DepthRangePass.h"
#include "DepthViewPass.h"
#include "FramePlan.h"
#include "FrameStats.h"
#include "FrameUpdate.h"
#include "GpuScene.h"
#include "GpuTimer.h"
#include "LightMath.h"
#include "LightFitting.h"
#include "LitPass.h"
#include "MeasureTarget.h"
#include "MomentsMap.h"
#include "RenderTarget.h"
#include "Settings.h"
#include "ShadowCache.h"
#include "ShadowMap.h"
#include "ShadowReach.h"
#include "ShadowStorage.h"
#include "ShadowTechnique.h"
#include "ShadowViewFrames.h"
#include "VirtualShadowMap.h"

#include <QRectF>

#include <memory>
#include <optional>

namespace shadowlab {

// The whole frame: shadow pass (only when its inputs changed), lit pass, and on request the
// depth-map view. Knows no widgets and creates no context: it is handed the current context's
// functions and a target. All GL resources belong to that context (textures are shareable);
// destroy the Renderer with the context current.
class Renderer {
public:
    explicit Renderer(GlFunctions* gl);
    ~Renderer();

    // Validates `settings` first: throws SettingsError (naming the key) or RenderError and then
    // leaves the last good state alone. A target of zero area draws nothing.
    void render(const Settings& settings, const RenderTarget& target, TimingMode timing = TimingMode::Async);

    // Renders `settings` at `size` with the lit pass's measuring variant and reads back, per
    // pixel, the world position, geometric normal and the very shadow term that was shaded.
    // Uses (and fills) the same shadow-map cache as render(). Throws like render().
    VisibilityBuffer renderVisibility(const Settings& settings, QSize size);

    // Draws the current shadow map (from the last render()) into `target` (over `viewport`, GL
    // pixels; empty: all of it), its colour ramp stretched to depthMapSpan().
    void renderDepthMap(const RenderTarget& target, const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0), const QRect& viewport = QRect());
    // The depth-map view's colour bar over `viewport`.
    void renderDepthLegend(const RenderTarget& target, const QRect& viewport);
    // The nearest and farthest depth written into the current map (nullopt: none), measured
    // once per shadow pass.
    std::optional<DepthSpan> depthMapSpan();

    const FrameStats& lastFrame() const { return m_stats; }
    const LightFrame& lightFrame() const { return m_light; }
    // The view depth range the last fit's cascades split with shadow.depth_fit = sdsm (nullopt:
    // not sdsm, or nothing drawn).
    const std::optional<VisibleDepthRange>& visibleDepthRange() const { return m_visibleRange; }
    const CameraFrame& cameraFrame() const { return m_camera; }
    const ShadowMap& shadowMap() const { return m_shadowMap; }
    // The moments map of the moment techniques; null until one is first used.
    const MomentsMap* momentsMap() const;
    // Which moment the depth-map view shows (1-4), or 0 when it shows depth.
    int depthMapMoment() const { return momentsShown() ? m_plan.settings.moments.view : 0; }
    // The min/max depth mip of the map for penumbra-only filtering; null until first needed.
    const DepthRangePass* depthRange() const { return m_depthRange.get(); }
    const Scene* scene() const { return m_scene ? &m_scene->scene() : nullptr; }
    // Renders `scene` instead of the preset that settings.scene names, until reset with nullopt
    // (for the audit's degenerate scenes; the `scene` key offers only the presets). Uploaded on
    // the next render().
    void setScene(std::optional<Scene> scene);
    // The scene of the model or scene file `path` that settings.scene names, loaded by the caller
    // before the frame (lab/SceneSupply.h): a frame builds a preset from the program's own
    // resources, and reads no file and starts no process itself. A frame whose settings name a
    // file other than the last one handed in throws RenderError.
    void setSceneFile(const QString& path, std::shared_ptr<const Scene> scene);
    // Whether the renderer holds file `path` as another load than `latest` (it changed on disk
    // since): a custom scene (setScene) holds none.
    bool holdsOlderSceneFile(const QString& path, const std::shared_ptr<const Scene>& latest) const;
    // Whether settings.scene is a file this renderer has not been handed (setSceneFile).
    bool needsSceneFile(const Settings& settings) const;
    // The light volume of the last frame after light.fit (the passes' volume), with what it cut.
    const FittedLight& lastFit() const { return m_update.fitted(); }
    // The views of the last frame when the light has several (cascades, cube faces); their
    // frames are empty otherwise.
    const ShadowViewFrames& shadowViews() const { return m_update.views(); }
    // Whether depth32f maps get reversed depth here (glClipControl: GL 4.5 or ARB_clip_control).
    bool supportsReversedDepth() const { return m_depthPass.supportsReversedDepth(); }
    // How many times the shadow pass has actually run (drawn a view) since construction.
    int shadowPassCount() const { return m_shadowPassCount; }
    // Counts every change of the map's content: a pass, or a view's tile cleared to lit.
    int mapGeneration() const { return m_mapGeneration; }
    // How many times the light's views were fitted; a frame whose inputs did not change does not.
    int fitCount() const { return m_update.fitCount(); }
    int compiledLitVariants() const { return m_litPass.compiledVariantCount(); }
    // Cut-out variants compiled so far, lit pass and shadow pass (none until a scene has cut-outs).
    int compiledCutoutVariants() const { return m_litPass.compiledCutoutVariantCount() + int(m_depthPass.hasCutoutVariant()); }
    // Fits the light to `camera` instead of settings.camera (which still draws the frame), until
    // reset with nullopt: what flicker measures, the shadow maps following a moving camera while
    // the measured pixels stay put.
    void setFitCamera(std::optional<CameraSettings> camera) { m_fitCamera = std::move(camera); }
    // Where the lookups of the last frame could find a caster (core/ShadowReach.h).
    const ShadowReach& shadowReach() const { return m_update.reach(); }
    // What the last frame resolved its settings into: the technique's row, the storage, the
    // tiles, the rasteriser profile's optimisations.
    const FramePlan& lastPlan() const { return m_plan; }
    // The virtual shadow map of shadow.virtual (null until first used): its layout, page cache
    // and windows as of the last frame.
    const VirtualShadowMap* virtualMap() const { return m_virtual.get(); }
    // Whether the virtual map reads its requests back a frame later (VirtualShadowMap::setAsyncRequests).
    void setVirtualAsyncRequests(bool async);
    // Forces the next render() to redraw the shadow map, as a moving light does (a map drawn
    // into slices, map.slices, goes on to its next one).
    void invalidateShadowMap() { m_shadowKey.reset(); }
    // shadow.cache=on-demand: the next frame draws the moving casters where its views are stale.
    void requestShadowRedraw() { m_redrawRequested = true; }

    // Whether frames count what transfers to any GPU (FrameCounts' query counts: primitives,
    // samples, lookup fragments). Off by default: the queries cost a software rasteriser a wait,
    // so benchmarks count in a frame of their own, never in a timed one.
    void setCounting(bool counting) { m_counting = counting; }

    QString rendererString() const;
    int maxTextureSize() const;

private:
    // Validation, scene, light and camera, and the shadow pass when its inputs changed; fills
    // the shadow-pass half of `stats`. Throws before touching any state when settings are bad.
    // `measure`: a measurement's frame, whose map is drawn into its first slice after a clear
    // (map.slices), so what is measured does not depend on the draws before it.
    void prepareFrame(const Settings& settings, QSize size, TimingMode timing, FrameStats& stats, bool measure = false);
    // Warns once where the plan wants reversed depth and the driver cannot give it.
    void warnOnce(const FramePlan& plan);
    // The map's tiles (a virtual map's pool: a slot per page) and the storage for them.
    void ensureMap(const FramePlan& plan, ShadowStorage& storage);
    // The scene the settings name, uploaded when it changed.
    void ensureScene(const Settings& settings);
    // A copy of the scene `settings` draw: the custom one, a preset's, or the file's handed in.
    Scene sceneOf(const Settings& settings) const;
    using SceneFile = std::pair<QString, std::shared_ptr<const Scene>>;
    // The file of `path` as last handed in, or as drawn now; null when neither.
    const SceneFile* fileFor(const QString& path) const;
    // The bounds of the moving objects as posed now, and whether each casts.
    struct MovingBounds {
        Bounds bounds;
        bool casts = false;
    };
    std::vector<MovingBounds> movingBounds() const;
    // Why this frame's shadow pass drew, from what changed since the last frame's settings.
    FrameStats::Redraw redrawReason(bool drawn, bool casterMoved, bool sceneChanged, const Settings& settings) const;
    // The fit of `frame`, with what it reads from passes: sdsm's visible depth, the virtual layout.
    void refit(const FrameUpdate::Frame& frame, const FramePlan& plan, const ShadowStorage& storage, FrameStats& stats);
    // The min/max depth mip of penumbra-only filtering, when the map changed; timed with the shadow pass.
    void buildDepthRange(const FramePlan& plan, TimingMode timing, FrameStats& stats);
    void finishTiming(TimingMode timing, FrameStats& stats);
    // The lit pass into `target` (with its camera depth prepass for contact shadows), timed.
    void drawLit(const FramePlan& plan, const RenderTarget& target, bool measure, FrameStats& stats);
    // The shadow pass's half of stats.counts, after it ran (or did not).
    void countShadowPass(const FramePlan& plan, ShadowStorage& storage, FrameStats& stats);
    // The shadow pass: the views (one, a cascade set or six faces, each a tile of the map)
    // whose volume changed, or every view when what they share did.
    // Under shadow.cache, a view a moving caster touched is drawn from its copy of the still
    // casters (ShadowCache).
    void renderViews(const FramePlan& plan, ShadowStorage& storage, bool castersMoved, TimingMode timing, FrameStats& stats);
    // Whether what all views share changed since they were drawn: then every one is due, for `cause`.
    bool beginViews(const FramePlan& plan, const ShadowStorage& storage, bool castersMoved, ViewCause& cause);
    // The scene generation the stored views depend on: with a cache, not on where casters are.
    int keyGeneration(const FramePlan& plan) const;
    // Per view, where in its square of `mapSize` texels each moving caster lies now.
    std::vector<std::vector<QRect>> movingTexels(int mapSize) const;
    std::vector<QRect> readTexels(const Settings& settings) const;
    // Each view's volume as it should be drawn: nullopt where it has nothing to shadow.
    std::vector<std::optional<LightVolume>> wantedVolumes() const;
    // The share of a map of `count` views its casters may cover (DepthSlices::setCasterCoverage).
    double casterCoverage(std::size_t count) const;
    // Whether this pass into a map of several tiles draws into a slice (map.slices); a kept view
    // with casters is drawn too where the pass moves the map to another slice.
    bool slicesViews(const FramePlan& plan, std::vector<ShadowCache::Decision>& decisions, const std::vector<std::optional<LightVolume>>& wanted) const;
    // View `i` drawn at `wanted`, or its tile cleared where it has nothing to shadow.
    // `movingNow`: where the moving casters lie in it (shadow.cache).
    void drawView(std::size_t i, const ShadowCache::Decision& decision, const std::optional<LightVolume>& wanted, const std::vector<QRect>& movingNow,
                  const FramePlan& plan, ShadowStorage& storage, TimingMode timing, FrameStats& stats);
    // shadow.virtual's shadow pass: the pages the frame's pixels need, drawn where new.
    void renderPages(const FramePlan& plan, ShadowStorage& storage, QSize size, TimingMode timing, FrameStats& stats);
    // The storage of the plan's technique (built on first use).
    ShadowStorage& storageFor(const FramePlan& plan);
    // The moments map the last frame's technique read, or null when it read depth.
    const MomentsMap* momentsShown() const;

    GlFunctions* m_gl;
    ShadowMap m_shadowMap;
    DepthPass m_depthPass;
    std::unique_ptr<ShadowStorage> m_depthStorage;
    std::unique_ptr<ShadowStorage> m_momentsStorage;  // built when a moment technique is first used
    LitPass m_litPass;
    std::unique_ptr<DepthViewPass> m_depthView;  // built on first use
    std::unique_ptr<DepthRangePass> m_depthRange;    // built when penumbra-only filtering is first used
    std::unique_ptr<CameraDepthPass> m_cameraDepth;  // built when contact shadows are first used
    std::unique_ptr<VisibleDepthPass> m_visibleDepth;  // built when sdsm cascades are first used
    std::unique_ptr<VirtualShadowMap> m_virtual;        // built when shadow.virtual is first used
    bool m_virtualAsync = false;
    VirtualMapUniforms m_virtualUniforms;               // the last frame's, for the lit pass
    std::optional<VisibleDepthRange> m_visibleRange;   // what the last fit split (sdsm)
    FramePlan m_plan;               // the last frame's
    int m_mapGeneration = 0;        // counts changes of the shadow map's content
    int m_depthRangeGeneration = -1;    // the map generation the depth range was built from
    int m_spanGeneration = -1;          // ... and the written span
    std::optional<DepthSpan> m_span;
    std::unique_ptr<GpuScene> m_scene;
    std::unique_ptr<MeasureTarget> m_measureTarget;   // built on first measurement
    GpuTimer m_shadowTimer;
    GpuTimer m_litTimer;
    bool m_counting = false;
    bool m_softwareDriver = false;      // GL_RENDERER names a software rasteriser (what rasteriser.profile=auto follows)
    CountQuery m_shadowPrimitives;
    CountQuery m_shadowSamples;
    CountQuery m_litPrimitives;
    std::optional<ShadowStorageKey> m_shadowKey;
    // Each view's volume as last drawn, redrawn only when it changes, and what shadow.cache
    // keeps of it; m_shadowKey holds what all views share.
    ShadowCache m_viewCache;
    bool m_redrawRequested = false;     // requestShadowRedraw()
    // Moves of the objects since the last shadow pass: whether any, and for shadow.cache=pages
    // each moving object's bounds over where it was and is.
    bool m_castersMoved = false;
    std::vector<MovingBounds> m_movedBounds;
    FrameUpdate m_update;           // the camera, the fitted views and their reach
    std::optional<Scene> m_customScene;
    std::optional<std::pair<QString, std::shared_ptr<const Scene>>> m_sceneFile;     // setSceneFile's path and scene
    std::optional<std::pair<QString, std::shared_ptr<const Scene>>> m_drawnFile;     // the file m_scene was built from
    std::optional<CameraSettings> m_fitCamera;
    bool m_sceneChanged = true;     // rebuild m_scene on the next frame
    ObjectSwitches m_objectSwitches;    // applied to m_scene
    int m_sceneGeneration = 0;      // counts new scenes and moves of their casters
    int m_shapeGeneration = 0;      // counts new scenes
    bool m_warnedNoReversedDepth = false;
    LightFrame m_light;
    CameraFrame m_camera;
    FrameStats m_stats;
    int m_shadowPassCount = 0;
    double m_lastShadowMs = 0.0;    // newest finished measurements, for TimingMode::Async
    double m_lastLitMs = 0.0;
};

} // namespace shadowlab
