#pragma once

#include "RasteriserTuning.h"
#include "Settings.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"

namespace shadowlab {

// A frame's decisions, resolved once from its settings before anything is drawn, as Filament's
// ShadowMapManager::update resolves its shadow maps before render: the technique's row, the
// storage, the tiles of the map and their depth convention, the optimisations the rasteriser
// profile turns on, and which extra passes the lit pass reads. The renderer's steps and the
// storages read the plan; the settings' values ride along for the uniforms they set.
struct FramePlan {
    Settings settings;
    const ShadowTechnique* technique = nullptr;     // filter.mode's row
    bool shadows = false;           // shadow.enabled
    bool virtualMap = false;        // a virtual map's pages (shadow.virtual, with shadows)
    bool moments = false;           // the technique stores moments, not depth
    bool severalViews = false;      // cascades or cube faces (usesShadowViews)
    bool lightWarp = false;         // a directional light's views may be warped (light.warp)
    ShadowTileGrid grid;            // tiles of the map: views side by side, or a virtual map's pool, a slot per page
    int tileSize = 0;               // texels per tile side
    bool reversedDepth = false;     // a depth32f map with reversed depth (not a moments map: its own format keeps precision)
    bool reversedDepthWanted = false;   // ... which the settings ask for, whether or not the driver has it
    int slices = 1;                 // draws of a plain depth24 map per clear (map.slices, where the tuning slices)
    bool earlyOut = false;          // penumbra-only filtering (filter.early_out) skips a footprint's taps where it can
    bool depthRange = false;        // the lit pass reads the map's min/max depth mip: early out, or a blocker search
    bool contactShadows = false;    // the lit pass marches over the camera's depth
    bool visibleDepth = false;      // sdsm cascades split the depth range the fitting camera draws
    int tapsPerLookup = 0;          // the technique's taps, 0 without shadows
    int lookupBlurRadius = 0;       // moments blurred in the lookup (moments.blur_at): its radius; 0 none
    ShadowCachePolicy cache = ShadowCachePolicy::Off;  // shadow.cache, off without shadows
    RasteriserTuning tuning;
};

// Pure and without GL, for valid `settings`. `softwareDriver`: the driver is a software
// rasteriser (what rasteriser.profile = auto follows); `reversedDepthSupported`: it has
// glClipControl (GL 4.5 or ARB_clip_control).
FramePlan planFrame(const Settings& settings, bool softwareDriver, bool reversedDepthSupported);

} // namespace shadowlab
