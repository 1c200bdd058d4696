#pragma once

#include "Bounds.h"
#include "FrustaClip.h"
#include "LightMath.h"
#include "Settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace shadowlab {

// One scene object as the fit sees it: a world box and its roles.
struct FitObject {
    Bounds bounds;
    bool casts = true;
    bool receives = true;
    bool convex = false;        // a convex object cannot shadow itself
};

// The light's volume from the scene, in double precision and without GL.
//
// With light.fit = scene the volume as set does not limit anything: a directional light is a
// direction, and its map covers, in light space, exactly the receivers the camera sees that a
// caster can shadow (a caster's part over a receiver and in front of it), with separate x and
// y extents and near/far as tight as those receivers allow (casters in front of the near plane
// still cast: the depth pass clamps their depth). A perspective light does the same with its
// cone (asymmetric, at most kMaxFittedFov wide) and near/far. The result does not depend on
// how far the light is from its target.
//
// With `stabilize` the fitted volume moves in whole texels and grows or shrinks in coarse
// steps, so a moving camera neither makes the shadow edges shimmer nor changes the volume,
// and the shadow map is reused, until the visible region crosses a step.
//
// With light.fit = manual the volume is exactly as set; receivers the camera sees outside it
// are lit without a shadow test, and the fit says how much of them and past which plane.
// A cut worth telling the user about: receivers outside the volume, lit without a shadow test.
struct FitCut {
    enum class By {
        ManualVolume,   // the volume as set (light.fit=manual)
        WidestCone,     // behind a perspective light, or outside the widest cone one map covers
    };
    By by = By::ManualVolume;
    bool perspective = false;
    double share = 0.0;
    std::array<double, 6> byPlane{};    // share outside each of left, right, bottom, top, near, far (ManualVolume)
    bool operator==(const FitCut&) const = default;
};

struct FittedLight {
    LightVolume volume;         // what the passes use
    bool fitted = false;        // false: manual fit
    bool anythingToShadow = true; // false: no caster can shadow a visible receiver (or no caster at all)
    double texelBefore = 0.0;   // world size of one texel with the volume as set
    double texelAfter = 0.0;    // ... and with the volume used
    // Share of the visible receivers' surface that lies outside the volume used, where it is
    // lit without a shadow test.
    double cutShare = 0.0;
    // Each cut worth a warning (one per view that cuts; fitWarnings() words them).
    std::vector<FitCut> cuts;
    // The camera's view depths of the receivers it sees (0, 0: none, or no camera; scene fit only).
    double seenNearDepth = 0.0, seenFarDepth = 0.0;
    // Fitted with LightVolume::up (for a warp): the outline of the receivers seen, in the
    // volume's own x and y, within its box; the warp needs to cover only that.
    std::vector<glm::dvec2> focus;
    // light.warp = lispsm: what the warp did (LightWarp.h), for the stats.
    bool warped = false;
    double warpNearDistance = 0.0;
    // Where a warp was asked for: how much finer it makes the texels nearest the camera than
    // the unwarped map (warpNearGain()), and why it was not drawn where it was not.
    double warpGain = 0.0;
    enum class WarpSkip { None, AlongLight, NoGain } warpSkip = WarpSkip::None;
};

// The widest cone a fitted perspective light covers (full angle, degrees): wider, a single map
// spends almost all of its texels at the rim.
inline constexpr double kMaxFittedFov = 150.0;

// The warnings a fit's cuts give, one per key, with the key to change and how: the user's words
// for what fitLight() measured.
std::vector<SettingsIssue> fitWarnings(const FittedLight& fit);

// `light` must be valid (validate()); objects' empty boxes are ignored; `camera` is the
// camera's view-projection (nullopt: everything is seen). `within`: further view-projections
// the receivers must lie in to count (a cascade's slice, a spot's cone, a cube face).
// `mapUp`: an ortho map's y axis in world (LightVolume::up); zero: stableLookAlong's.
FittedLight fitLight(const LightSettings& light, const std::vector<FitObject>& objects, const std::optional<glm::dmat4>& camera,
                     int mapSize, const std::vector<glm::dmat4>& within = {},
                     const glm::dvec3& mapUp = glm::dvec3(0.0));

// The camera's visible region as the light's map sees it: `box` (the scene) clipped to the
// camera's frustum (`cameraViewProjection`), projected by `shadowMatrix` (world -> map [0, 1]^2)
// and wrapped in its convex hull, counter-clockwise. Points behind a perspective light are left
// out. Empty when the camera sees nothing of the box. For the depth-map view's outline.
std::vector<glm::dvec2> cameraFootprint(const Bounds& box, const glm::dmat4& cameraViewProjection, const glm::dmat4& shadowMatrix);

// The convex hull of `points`, counter-clockwise (fewer than 3 points: as given).
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points);

// The outline a warped map must cover (FittedLight::focus): the hull of `points` (light space
// x, y) grown by `margin` (world units), within the window of `span` around `centre`, in the
// window's own coordinates (centre at 0). Empty when it has no area there.
std::vector<glm::dvec2> focusOutline(std::vector<glm::dvec2> points, const glm::dvec2& centre, const glm::dvec2& span, double margin);

} // namespace shadowlab
