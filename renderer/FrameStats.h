#pragma once

#include <QString>

#include <cstdint>
#include <utility>
#include <vector>

namespace shadowlab {

// Why a view (or a virtual map's page) holds what it holds this frame: the depth pane's
// colours and the status bar's counts, as Unreal's cache visualisation shows its pages.
enum class ViewCause {
    Cached,         // kept from an earlier frame, and right
    Stale,          // kept although a moving caster left it out of date (every-n, on-demand)
    Unseen,         // kept although a moving caster left it out of date where no pixel reads it
    Casters,        // drawn again because a moving caster touched it
    Light,          // drawn again because its volume changed (the light moved, or the fit did)
    New,            // drawn because what every view shares changed (the scene, a setting) or first
};
QString toString(ViewCause cause);

// What a frame of a virtual shadow map did, for FrameStats and the window.
struct VirtualMapStats {
    int requested = 0;          // distinct pages the visible pixels asked for
    int resident = 0;           // pages held in the pool after the frame
    int drawn = 0;              // pages drawn this frame (new, or invalid)
    int invalidated = 0;        // ... of which resident, drawn again because a moving caster touched them (shadow.cache=pages)
    int coarsened = 0;          // requests served a coarser level than asked, the pool being too small
    int levelsCoarsened = 0;    // ... by at most this many levels
    int overflow = 0;           // coarsest-level pages that did not fit at all
    int poolPages = 0;
    int finestLevel = -1;       // the finest level that serves one of the requests; -1 none
    int requestDraws = 0;       // draw calls of the request pass (0 when the requests were kept)
    bool requestsPending = false;   // asynchronous requests (the window) still on their way back
};

// Costs that are the same on any GPU, unlike times: what a frame asked of the rasteriser.
// Query counts are -1 unless the frame was counted (Renderer::setCounting: their queries cost a
// software rasteriser a wait, so a timed frame is never a counted one).
struct PassCounts {
    int draws = 0;                      // draw calls
    std::int64_t primitives = -1;       // GL_PRIMITIVES_GENERATED
    std::int64_t samples = -1;          // GL_SAMPLES_PASSED: fragments that passed the depth test
};

struct FrameCounts {
    // The shadow pass: casters, and a moments map's far-plane fill and blur; a virtual map's
    // request pass (the camera's pixels asking for pages) too.
    PassCounts shadow;
    PassCounts lit;
    std::int64_t clearedTexels = 0;     // shadow-map texels cleared (or filled with the far plane's moments)
    std::int64_t blurTexels = 0;        // texels the moments blur wrote, both axes
    std::int64_t blurBytes = 0;         // bytes it read and wrote
    std::int64_t copiedTexels = 0;      // texels shadow.cache copied to and from its copies
    std::int64_t cacheBytes = 0;        // the memory of those copies
    std::int64_t mapBytes = 0;          // the shadow storage's memory (page pool and table for a virtual map)
    int tapsPerLookup = 0;              // the technique's texture reads per lookup, at most (ShadowTechnique::taps)
    std::int64_t lookupFragments = -1;  // lit fragments that looked the shadow up (counted frames)
    // Shadow texture reads of the frame: taps per lookup times the fragments that looked up.
    std::int64_t taps() const { return lookupFragments < 0 ? -1 : lookupFragments * tapsPerLookup; }
    bool counted() const { return shadow.samples >= 0 || lit.samples >= 0; }
};

// What one frame cost and did. GPU times come from GL_TIME_ELAPSED (0 on a software renderer,
// which runs no timer query: its wall times are the measure there). With TimingMode::Finish they are this frame's; with Async, the newest
// finished measurement of each pass, which may be a frame or two old.
struct FrameStats {
    double shadowPassMs = 0.0;          // with Finish: 0 when the pass was reused or shadows are off
    double litPassMs = 0.0;
    double frameWallMs = 0.0;           // render() to after glFinish; only with TimingMode::Finish
    double shadowPassWallMs = 0.0;      // wall time of each pass between glFinish calls; only with
    double litPassWallMs = 0.0;         // TimingMode::Finish (a software renderer's timer queries miss
                                        // its deferred rasterisation, the wall clock does not)
    double blurPassWallMs = 0.0;        // of shadowPassWallMs, the moments blur and mip build (moment techniques)
    bool shadowPassRendered = false;    // false: the cached map was reused, or shadows are off
    // Why it was drawn: what changed since the frame before (the first that applies).
    enum class Redraw { None, Scene, Casters, Light, Camera, Settings } redraw = Redraw::None;
    int shadowDraws = 0;                // casters drawn by the shadow pass (0 when reused)
    bool shadowMapCleared = false;      // the pass cleared the map (map.slices: once in that many passes)
    int litDraws = 0;                   // draw calls (a receiver straddling the shadow reach counts twice)
    // Of the lit pass's draws, those of receivers that no caster reaches, shaded without a
    // shadow lookup (core/ShadowReach.h), and whether it masked straddling receivers by stencil.
    int litPlainDraws = 0;
    bool litReachMasked = false;
    // Casters the lit pass drew into the camera's depth for contact shadows (0: kept, or off).
    int contactDepthDraws = 0;
    // Objects drawn into the depth prepass sdsm cascades are split by (0: kept, or not sdsm).
    int visibleDepthDraws = 0;
    double texelWorldSize = 0.0;        // world units covered by one shadow-map texel, as rendered (after light.fit)
    double texelWorldSizeBeforeFit = 0.0; // ... with the light volume as set
    bool lightFitted = false;           // light.fit = scene shrank the volume this frame
    bool reversedDepth = false;         // the map was rendered with reversed depth (depth32f and clip control)
    bool softwareProfile = false;       // drawn with a software rasteriser's optimisations (RasteriserTuning)
    // light.warp = lispsm: the views it warped, of `warpViews` (0 of 0: not asked for), how
    // much finer it makes the texels nearest the camera (the first view's gain, drawn or
    // declined) and, where it warped none, why (LightWarp.h).
    int warpViews = 0;
    int warpedViews = 0;
    double warpGain = 0.0;
    enum class WarpDeclined { No, AlongLight, NoGain } warpDeclined = WarpDeclined::No;
    // Lights with several views (cascades, cube faces): per view, whether it was drawn this
    // frame (one without casters is not: at most cleared where it was written), its casters
    // drawn and (TimingMode::Finish) its wall time; empty for one map.
    std::vector<bool> viewRendered;
    std::vector<int> viewDraws;
    std::vector<double> viewWallMs;
    // Why each view holds what it holds (ShadowCache.h): the depth pane's colours; for a
    // virtual map, per slot of its pool. And the memory of the copies shadow.cache keeps.
    std::vector<ViewCause> viewCauses;
    std::vector<std::pair<int, ViewCause>> pageCauses;     // shadow.cache=pages: per resident slot
    std::int64_t cacheBytes = 0;
    // What transfers to any GPU (see FrameCounts); shadow.* of a frame that drew no shadow
    // pass are zero.
    FrameCounts counts;
    // shadow.virtual: what the frame's pages did (all 0 otherwise).
    bool virtualMap = false;
    VirtualMapStats virtualPages;
};

enum class TimingMode {
    Async,  // interactive: never stall, report the newest finished GPU times
    Finish, // measurement: glFinish after each pass and wait for this frame's times
};

} // namespace shadowlab
