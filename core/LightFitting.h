#pragma once

#include "Bounds.h"
#include "Settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace shadowlab {

// The light's volume shrunk to what matters, in double precision and without GL.
//
// "What can be seen" is every receiver box clipped to the camera's frustum and to the light's
// volume as set: the set volume is an upper bound (up to the snapping margin of `stabilize`,
// at most 1/16 of the fitted size), the camera frustum is what makes the fit worth having on scenes with a
// large ground plane. "What can cast onto it" is every caster whose light-space box overlaps
// that region in the map plane and is not entirely behind it. The fitted volume keeps the
// light's direction (an ortho light moves sideways, a perspective light narrows its cone) and
// covers exactly those, with near and far as tight as the casters and receivers allow.
//
// With `stabilize` the fitted volume moves in whole texels and grows or shrinks in coarse
// steps, so a moving camera neither makes the shadow edges shimmer nor changes the volume,
// and the shadow map is reused, until the visible region crosses a step.
struct FittedLight {
    LightSettings light;        // the volume the passes use (the input when nothing changed)
    bool fitted = false;        // false: manual fit, or the fit could not shrink the volume
    bool anythingToShadow = true; // false: no caster can shadow a visible receiver (or no caster at all)
    double texelBefore = 0.0;   // world size of one texel with the volume as set
    double texelAfter = 0.0;    // ... and with the fitted volume
};

// `light` must be valid (validate()); casters and receivers are world-space boxes (empty ones
// are ignored); `camera` is the camera's view-projection (nullopt: everything is seen).
FittedLight fitLight(const LightSettings& light, const std::vector<Bounds>& casters, const std::vector<Bounds>& receivers,
                  const std::optional<glm::dmat4>& camera, int mapSize);

// The vertices of the convex region `box` ∩ each frustum (conventional clip space of each
// view-projection): empty when they do not overlap. Exposed for tests of the fit.
std::vector<glm::dvec3> clipBoxToFrusta(const Bounds& box, const std::vector<glm::dmat4>& viewProjections);

} // namespace shadowlab
