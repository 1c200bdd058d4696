#pragma once

#include "Bounds.h"
#include "Settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace shadowlab {

// Everything the passes need to know about the light, in double precision. Pure functions,
// no GL: computed once per change and converted to float only at upload.
// The box (ortho) or pyramid (perspective) the shadow map covers, in the light's view space:
// x and y across the map, depth along the light's direction. A directional light's volume is
// anchored at any point of its axis: its shadow depends on the direction alone.
struct LightVolume {
    glm::dvec3 origin{0.0};             // ortho: a point on the axis; perspective: the light's position
    glm::dvec3 direction{0.0, -1.0, 0.0}; // unit
    bool perspective = false;
    // Ortho: world units from the axis; perspective: tangents of the angle from the axis.
    double left = -1.0, right = 1.0, bottom = -1.0, top = 1.0;
    double nearPlane = 1.0;             // along the direction from the origin; perspective: > 0
    double farPlane = 10.0;
    // light.warp = lispsm (LightWarp.h): a perspective across the map, light view space to clip,
    // that replaces the ortho box's projection. The box above is still what the map covers.
    bool warped = false;
    glm::dmat4 warp{1.0};
    // The map's y axis in world (across the light): zero for stableLookAlong's; a warped
    // volume is fitted with its y along the camera's view, the axis of its warp.
    glm::dvec3 up{0.0};

    double width() const { return right - left; }
    double height() const { return top - bottom; }
    bool operator==(const LightVolume&) const = default;
};

struct LightFrame {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    glm::dmat4 viewProjection{1.0};
    glm::dmat4 shadowMatrix{1.0};       // world -> shadow-map texture coordinates and depth, [0, 1]^3
    // What the GL passes use: equal to viewProjection and shadowMatrix, except with reversed
    // depth (glClipControl zero-to-one), where clip z runs from w at near to 0 at far and the
    // stored depth is 1 - the conventional one. Culling and tests use the conventional pair.
    bool reversedDepth = false;
    glm::dmat4 depthViewProjection{1.0};
    glm::dmat4 depthShadowMatrix{1.0};
    LightVolume volume;                   // what the matrices cover
    glm::dvec3 position{0.0};             // the light as set (a directional light's volume ignores it)
    glm::dvec3 direction{0.0, -1.0, 0.0}; // unit, from the light toward its target
    double targetDistance = 1.0;          // from the light to its target
    bool perspective = false;
    double nearPlane = 1.0;
    double farPlane = 10.0;
    // A spot light's cone: the cosine of its half-angle (light.fov); receivers outside it are
    // unlit. Below -1 for lights without a cone.
    double spotCosine = -2.0;
    bool operator==(const LightFrame&) const = default;
};

struct CameraFrame {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    glm::dmat4 viewProjection{1.0};
    glm::dvec3 position{0.0};
    double nearPlane = 0.1;
    double farPlane = 100.0;
};

// Where a light sits around its target, as people turn it: azimuth in degrees around the
// vertical (0 toward +z, 90 toward +x, in (-180, 180]), elevation in degrees above the
// horizontal plane ([-90, 90]), and distance in world units. The dock's direction fields and
// a Ctrl-drag in the scene view edit light.position through these.
struct LightAngles {
    double azimuth = 0.0;
    double elevation = 0.0;
    double distance = 0.0;
};
// Straight above or below, the azimuth is undefined and `previousAzimuth` is kept.
LightAngles lightAngles(const glm::dvec3& position, const glm::dvec3& target, double previousAzimuth = 0.0);
glm::dvec3 lightPosition(const glm::dvec3& target, const LightAngles& angles);

// A right-handed look-at whose up vector is chosen away from the view direction, so a light
// straight above or below its target still gets an orthonormal, finite basis.
// Requires eye != target (see validate()).
glm::dmat4 stableLookAt(const glm::dvec3& eye, const glm::dvec3& target);
// The same, looking from `eye` along `direction` (any length > 0), with `up` as its y axis
// where it is given (non-zero, not along the direction; only its part across the direction
// counts).
glm::dmat4 stableLookAlong(const glm::dvec3& eye, const glm::dvec3& direction, const glm::dvec3& up = glm::dvec3(0.0));

// The volume exactly as set: light.extent, light.fov, light.near and light.far around the axis
// from light.position toward light.target. Throws SettingsError for settings that cannot make
// one (light at its target, near >= far, non-positive perspective near, ...).
LightVolume manualVolume(const LightSettings& light);

// The frame of `light` whose matrices cover `volume` (fitting is LightFitting.h's job).
// Throws SettingsError when the volume cannot make finite matrices: callers get a message,
// never a NaN matrix.
LightFrame computeLightFrame(const LightSettings& light, const LightVolume& volume, bool reversedDepth = false);
// The frame of the volume as set.
LightFrame computeLightFrame(const LightSettings& light, bool reversedDepth = false);

// The camera's matrices for a viewport of the given aspect ratio; near and far enclose
// `sceneBounds` so nothing of the scene is clipped.
CameraFrame computeCameraFrame(const CameraSettings& camera, double aspect, const Bounds& sceneBounds);

// World-space width of one shadow-map texel (the wider axis): for an ortho volume across the
// whole map, for a perspective one at `distance` from the light, for a warped one the coarsest
// over its box.
double texelWorldSize(const LightVolume& volume, int mapSize, double distance = 1.0);
// A warped volume's texel (the wider axis) at a point of its box, in light view space
// (x, y across the map, z = -depth): its world size there.
double warpedTexelSize(const LightVolume& volume, int mapSize, const glm::dvec3& lightViewPoint);
// ... of the volume as set, at the target's distance for a perspective light.
double texelWorldSize(const LightSettings& light, int mapSize);

// True when `box` lies entirely outside the frustum of `viewProjection` on one side.
// With `ignoreNear` the near plane does not cull (casters before it still cast under depth clamp).
bool isOutsideFrustum(const glm::dmat4& viewProjection, const Bounds& box, bool ignoreNear);

// The 8 corners of the frustum of `viewProjection` (conventional clip space) in world space.
std::array<glm::dvec3, 8> frustumCorners(const glm::dmat4& viewProjection);

// True when every element of the matrix is finite.
bool isFinite(const glm::dmat4& m);

} // namespace shadowlab
