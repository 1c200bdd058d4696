#pragma once

#include "CasterTexels.h"
#include "FrameStats.h"
#include "LightFitting.h"
#include "LightMath.h"
#include "SceneLayout.h"
#include "Settings.h"
#include "ShadowReach.h"
#include "ShadowViewFrames.h"
#include "ShadowViews.h"
#include "VirtualPages.h"

#include <QSize>

#include <optional>

namespace shadowlab {

struct FramePlan;

// The frame's pure half, as Filament splits update() from render(): from the settings, the
// frame's size and the scene's layout, the cameras, the light's views fitted to what the fitting
// camera sees, and where lookups can find a caster. The fit is a pure function of its inputs,
// so when none changed (a still frame, a window repaint) the last one stands: for the city that
// is 2,000 objects clipped against the view each frame, left out. No GL: the renderer runs the
// passes it plans, and it is tested without a context.
class FrameUpdate {
public:
    // What the fit is computed from: when all of it is as last time, the fit stands.
    struct Inputs {
        int sceneGeneration = 0;                    // the scene's objects and shapes
        int poseGeneration = 0;                     // ... and where its moving objects are
        Settings settings;
        std::optional<CameraSettings> fitCamera;    // fit to this instead of settings.camera
        QSize size;
        bool reversed = false;                      // depth32f with reversed depth
        bool operator==(const Inputs&) const = default;
    };
    // A frame's cameras, and whether its fit is due.
    struct Frame {
        Inputs inputs;
        CameraFrame camera;         // draws the frame
        CameraFrame fitCamera;      // the light is fitted to: the frame's, or Inputs::fitCamera's
        double aspect = 1.0;
        bool refit = false;         // an input changed since the last fit
        // Only moving objects did: the views stand (fitted to everywhere they go), and only
        // what depends on where casters are now (the reach, the casters' texels) follows.
        bool reposeOnly = false;
    };
    // What a fit reads besides the scene: results of passes run for it, and the storage's culling.
    struct FitSources {
        std::optional<VisibleDepthRange> visibleRange;     // sdsm: the depth range the fitting camera draws
        std::optional<VirtualLayout> virtualLayout;        // shadow.virtual: one view, its coarsest level
        bool cullsFrontFaces = false;                      // the shadow pass culls front faces (for the reach)
        bool floorsLeftOut = false;                        // ... and leaves floors out (bias.skip_floors)
        bool reach = true;                                 // the reach is read (the software profile's lookups and slices)
    };

    Frame begin(Inputs inputs, const Bounds& sceneBounds) const;
    // Fits the light's views to `frame`'s fitting camera and finds their reach; a no-op when
    // the frame needs no refit.
    void fit(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources);

    // The last fit: every view with its light frame, the fit the window and warnings show (the
    // first view's volume with every view's cuts), and where lookups can find a caster.
    const ShadowViewFrames& views() const { return m_views; }
    const FittedLight& fitted() const { return m_fit; }
    const ShadowReach& reach() const { return m_reach; }
    // Per view, the texels its shadow pass can write (empty without shadows).
    const std::vector<CasterTexels>& casterTexels() const { return m_casterTexels; }
    // How many times the views were fitted.
    int fitCount() const { return m_fitCount; }
    // The fit's half of the frame's statistics: texel sizes before and after, and the warp.
    void describe(const FramePlan& plan, FrameStats& stats) const;

private:
    void findReach(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources);
    // The parts of findReach kept between fits, each found again when what it follows changed.
    void keepCasters(const Frame& frame, const Scene& scene, const SceneLayout& layout, const FitSources& sources);
    void keepStillTexels(int mapSize);
    void keepReachBoxes(const Settings& settings, const Scene& scene, const SceneLayout& layout);

    std::optional<Inputs> m_inputs;
    ShadowViewFrames m_views;
    FittedLight m_fit;
    ShadowReach m_reach;
    std::vector<CasterTexels> m_casterTexels;
    // The scene's casters, the still ones and the moving ones, kept while what they are found
    // from stands: the still ones' key has no pose (-1).
    struct CastersKey {
        int sceneGeneration = -1;
        int poseGeneration = -1;
        bool cullsFrontFaces = false;
        bool floorsLeftOut = false;
        bool operator==(const CastersKey&) const = default;
    };
    std::optional<CastersKey> m_stillKey, m_movingKey;
    std::vector<ReachObject> m_still, m_moving;
    // Per view, the texels of the casters that do not move, and what they were found for.
    struct StillTexelsKey {
        CastersKey casters;
        int mapSize = 0;
        std::vector<LightFrame> views;
        bool operator==(const StillTexelsKey&) const = default;
    };
    std::vector<CasterTexels> m_stillTexels;
    std::optional<StillTexelsKey> m_stillTexelsKey;
    // The reach's boxes of every caster, and what they were found for.
    struct ReachBoxesFor {
        CastersKey casters;
        int mapSize = 0;
        std::vector<LightFrame> views;
        ReachBoxesKey settings;
        bool operator==(const ReachBoxesFor&) const = default;
    };
    std::optional<ReachBoxes> m_reachBoxes;
    std::optional<ReachBoxesFor> m_reachBoxesFor;
    int m_fitCount = 0;
};

// The scene's objects as casters, one by one: a flat one-sided one whose front faces the pass
// culls (bias.cull_front), or a floor it leaves out (bias.skip_floors), with its plane; all of
// them, or the still or the moving ones.
ReachObject sceneCaster(const Scene& scene, const SceneLayout& layout, std::size_t i, bool cullsFrontFaces, bool floorsLeftOut);
std::vector<ReachObject> sceneCasters(const Scene& scene, const SceneLayout& layout, bool cullsFrontFaces, bool floorsLeftOut,
                                      CasterSet set = CasterSet::All);
// The receivers as drawn, for the reach.
std::vector<ReachObject> sceneReceivers(const SceneLayout& layout);

} // namespace shadowlab
