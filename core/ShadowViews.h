#pragma once

#include "LightFitting.h"
#include "LightMath.h"
#include "Settings.h"

#include <glm/vec3.hpp>

#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

// The most views one light renders: six cube faces (cascades are at most kMaxCascades).
inline constexpr int kMaxShadowViews = 6;

// One map a light renders: a cascade of a directional light, a face of a point light, or the
// single map of any light. Its volume is fitted like the single map's (LightFitting.h), within
// its own slice of the camera's view or its own face.
struct ShadowView {
    FittedLight fit;
    int column = 0, row = 0;            // its tile in the shared texture (map.size² texels each)
    double splitNear = 0.0;             // cascades: the slice of the camera's view depth it covers
    double splitFar = 0.0;
    glm::dvec3 axis{0.0, -1.0, 0.0};    // point lights: the face's axis (+x, -x, +y, -y, +z, -z)
};

struct ShadowViewSet {
    std::vector<ShadowView> views;
    int columns = 1, rows = 1;          // tiles of the shared texture
    bool cascaded = false;
    bool cube = false;
};

// Whether `settings` render more than one view (cascades > 1 or a point light).
bool usesShadowViews(const Settings& settings);
// Whether `settings` warp a directional light's views (light.warp = lispsm), so the lit pass
// takes each pixel's texel from the map's warp.
bool usesLightWarp(const Settings& settings);
// Whether the cascades of `settings` split the frame's drawn depth range (shadow.depth_fit = sdsm
// on a directional light's cascades, shadows on), which a depth prepass measures.
bool usesVisibleDepth(const Settings& settings);
// Whether a map of `settings` may be drawn into depth slices (map.slices, DepthSlices::beginDraw):
// one plain ortho view, whose depth is linear in distance, or a point light's six faces, which
// clear a tile each under a scissor otherwise (as dear to a software rasteriser as a draw over
// its texels); the renderer clears them instead where a face's far / near leaves a slice too
// few depth steps (Renderer::slicesViews). A spot or warped map's depth steps are spent near
// the light (or the warp's centre), and its one view clears whole, the fast clear. Cascades
// are drawn as the camera moves, a virtual map's pool clears each page it draws, and a cached
// map (shadow.cache) starts each frame from its copy, which writes every texel as a clear does.
bool slicesDepth(const Settings& settings);

// The tiles of the shared texture the light's views need: 3 x 2 cube faces, cascades two to a
// row, 1 x 1 for one map.
struct ShadowTileGrid {
    int columns = 1, rows = 1;
};
ShadowTileGrid shadowTileGrid(const Settings& settings);

// count + 1 view depths from nearPlane to farPlane (both > 0, near < far): where each cascade
// starts and ends. Uniform slices are equal in depth, logarithmic ones in ratio, practical ones
// are lambda * logarithmic + (1 - lambda) * uniform. Finite and increasing for any finite input.
std::vector<double> cascadeSplits(CascadeSplit scheme, double lambda, double nearPlane, double farPlane, int count);

// The six faces' axes in the order the shader picks them: +x, -x, +y, -y, +z, -z.
const std::vector<glm::dvec3>& cubeFaceAxes();

// The full angle of a cube face's map, a little over 90° so a filter's taps next to a face's
// edge still read that face's own texels.
double cubeFaceFov(int mapSize);

// The view depths (distance along the camera's view direction) of the nearest and farthest
// pixels drawn: what shadow.depth_fit = sdsm splits cascades over.
struct VisibleDepthRange {
    double nearest = 0.0;
    double farthest = 0.0;
};

// The view depths cascades split, from near to far: the camera's near plane to shadow.distance
// (and its far plane), or with shadow.depth_fit = sdsm and `visible` the drawn range within it,
// padded by `kSdsmPadding` each way (the depth buffer's rounding, and a frame drawn at another
// size than the one measured). Without `visible` (nothing
// drawn, or its numbers not finite) or with all of it beyond the distance, sdsm falls back to the
// distance's range. Always near < far, finite.
inline constexpr double kSdsmPadding = 0.02;
std::pair<double, double> cascadeDepthRange(const Settings& settings, const CameraFrame& camera,
                                            const std::optional<VisibleDepthRange>& visible);

// Every view of the light in `settings` for the camera `camera` (viewport aspect `aspect`):
// cascades (shadow.cascades > 1), six cube faces (light.type = point) or the one map. A view
// with nothing to shadow has fit.anythingToShadow false and need not be rendered. `visible`:
// the frame's drawn depth range, for shadow.depth_fit = sdsm. `settings` must be valid.
ShadowViewSet fitShadowViews(const Settings& settings, const std::vector<FitObject>& objects, const CameraFrame& camera, double aspect,
                             const std::optional<VisibleDepthRange>& visible = std::nullopt);

// A cascade's ortho volume from the bounding sphere of its slice of the camera's view: the same
// size however the camera turns, its centre snapped to whole texels, so camera motion moves
// shadow edges by whole texels only (no shimmer) and rarely changes the map. Depth covers the
// objects under it. `slice` is the slice's view-projection.
// `mapUp`: the map's y axis (LightVolume::up), zero for stableLookAlong's.
FittedLight fitCascadeSphere(const LightSettings& light, const std::vector<FitObject>& objects, const glm::dmat4& slice, int mapSize,
                             const glm::dvec3& mapUp = glm::dvec3(0.0));

} // namespace shadowlab
