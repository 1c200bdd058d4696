#pragma once

#include "Bounds.h"
#include "Settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace shadowlab {

// Everything the passes need to know about the light, in double precision. Pure functions,
// no GL: computed once per change and converted to float only at upload.
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
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, -1.0, 0.0}; // unit, from the light toward its target
    double targetDistance = 1.0;          // from the light to its target
    bool perspective = false;
    double nearPlane = 1.0;
    double farPlane = 10.0;
};

struct CameraFrame {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    glm::dmat4 viewProjection{1.0};
    glm::dvec3 position{0.0};
    double nearPlane = 0.1;
    double farPlane = 100.0;
};

// A right-handed look-at whose up vector is chosen away from the view direction, so a light
// straight above or below its target still gets an orthonormal, finite basis.
// Requires eye != target (see validate()).
glm::dmat4 stableLookAt(const glm::dvec3& eye, const glm::dvec3& target);

// Throws SettingsError for settings that cannot make a frame (light at its target, near >= far,
// non-positive perspective near, ...): callers get a message, never a NaN matrix.
// `light` is used as given (fitting is LightFitting.h's job).
LightFrame computeLightFrame(const LightSettings& light, bool reversedDepth = false);

// The camera's matrices for a viewport of the given aspect ratio; near and far enclose
// `sceneBounds` so nothing of the scene is clipped.
CameraFrame computeCameraFrame(const CameraSettings& camera, double aspect, const Bounds& sceneBounds);

// World-space width of one shadow-map texel: across the whole map for an ortho light, at
// the target's distance for a perspective one.
double texelWorldSize(const LightSettings& light, int mapSize);

// True when `box` lies entirely outside the frustum of `viewProjection` on one side.
// With `ignoreNear` the near plane does not cull (casters before it still cast under depth clamp).
bool isOutsideFrustum(const glm::dmat4& viewProjection, const Bounds& box, bool ignoreNear);

// The 8 corners of the frustum of `viewProjection` (conventional clip space) in world space.
std::array<glm::dvec3, 8> frustumCorners(const glm::dmat4& viewProjection);

// True when every element of the matrix is finite.
bool isFinite(const glm::dmat4& m);

} // namespace shadowlab
