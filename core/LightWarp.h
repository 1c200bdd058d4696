#pragma once

#include "LightMath.h"

#include <glm/vec2.hpp>

#include <vector>

namespace shadowlab {

// Light-space perspective shadow maps (Wimmer, Scherzer and Purgathofer 2004), for a directional
// light's ortho volume: a perspective across the map, looking along the camera's view direction
// as the map sees it, that gives receivers near the camera more texels and far ones fewer.
//
// The warp keeps the light directional: its rays stay parallel lines of the map (each ray one
// texel), and along a ray the stored depth stays linear in distance. So a bias moved along the
// ray, the filters' taps and a texel's depth slope keep their meaning; only the world size of a
// texel varies over the map, and the lit pass takes it per pixel.

// Below this sine of the angle between the view and the light, no warp: the camera looks along
// the light (toward it or with it at its back), where the warp's axis is undefined. Up to
// kWarpFadeEnd the warp fades out smoothly (its near distance grows without bound), so turning
// the camera never makes the map jump in size.
inline constexpr double kWarpFadeStart = 0.02;
inline constexpr double kWarpFadeEnd = 0.1;
// A weaker warp than this (near distance over the box's depth along the warp) changes texel
// sizes by under 0.1 % across the map: no warp is drawn instead.
inline constexpr double kWarpLongest = 1e3;

struct WarpFocus {
    double nearDepth = 0.1;     // the camera's view depths the map's receivers span
    double farDepth = 100.0;
    double scale = 1.0;         // light.warp_scale: times Wimmer's n_opt
    // What the map must cover across the light, in the box's x and y (FittedLight::focus); the
    // whole box where empty. Over the box's whole depth either way.
    std::vector<glm::dvec2> outline;
};

// What the warp did, for the stats and the tests.
struct WarpShape {
    bool warped = false;
    double sinGamma = 0.0;      // sine of the angle between the view and the light direction
    double nearDistance = 0.0;  // n: from the warp's centre to the box, along its axis
    double depth = 0.0;         // d: the box's depth along that axis
};

// The map's y axis for a warp: the camera's view direction across the light's `direction`,
// zero where the camera looks (nearly) along the light. Fitting the volume in that basis
// (LightVolume::up) keeps the warp's frustum tight around it.
glm::dvec3 warpAxis(const CameraFrame& camera, const glm::dvec3& direction);

// `box` (an unwarped ortho volume) with light.warp = lispsm for `camera`: warped = true and the
// warp's projection set, or `box` as given where the camera looks along the light or the warp
// would change nothing. The warp covers the focus's outline over the box's depth (the whole
// box without one). Finite for any finite input.
LightVolume lispsmVolume(const LightVolume& box, const CameraFrame& camera, const WarpFocus& focus, WarpShape* shape = nullptr);

// How much finer the `warped` volume's texels are than the `plain` one's (an unwarped fit of the
// same map) at the focus's point nearest the camera, where the warp is for: the ratio of their
// texels' world sizes (geometric mean of the two axes), above 1 where the warp gains. A warp
// fitted in a turned basis can cover more than the plain map does (a long, thin footprint of
// casters turned across it) and lose even there: then it is not worth drawing. 1 where it
// cannot be told (no focus in front of the camera).
double warpNearGain(const LightVolume& warped, const LightVolume& plain, int mapSize, const CameraFrame& camera,
                    const std::vector<glm::dvec2>& outline);

// Below this gain the unwarped map is drawn instead: a warp that makes the nearest texels
// under 10 % finer is not worth its per-pixel lookups and the coarser far field it costs.
inline constexpr double kWarpLeastGain = 1.1;

} // namespace shadowlab
