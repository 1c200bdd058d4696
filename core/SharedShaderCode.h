#pragma once

#include "ShaderConstants.h"
#include "VirtualPages.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/vector_relational.hpp>

namespace shadowlab::glsl {

// GLSL that C++ runs too: the shaders' own files under shaders/shared/, compiled here as C++ over
// GLM, whose types and functions are GLSL's. So a decision the GPU makes per pixel (which view,
// which virtual level and page, what a sliced depth means, the density tint's colour) and the
// CPU makes again (a measurement, a read-back, a legend) is written once.
//
// Those files keep to what both languages read alike: pure functions of their parameters (no
// uniforms, no `out` parameters, no arrays, no #include), float literals with an `f` (GLSL 3.30
// reads it; C++ would otherwise compute in double), and the constants both sides declare
// (ShaderConstants.h, VirtualPages.h). tst_SharedShaderCode runs each function on the GPU and
// here, and compares.
using namespace glm;

// The colour constants as the shaders see them (vec3), not as C++ keeps them.
inline constexpr vec3 asVec3(const Rgb& c) { return {c[0], c[1], c[2]}; }
inline constexpr vec3 kDensityBlue = asVec3(shadowlab::kDensityBlue);
inline constexpr vec3 kDensityGreen = asVec3(shadowlab::kDensityGreen);
inline constexpr vec3 kDensityYellow = asVec3(shadowlab::kDensityYellow);
inline constexpr vec3 kDensityRed = asVec3(shadowlab::kDensityRed);

// GLSL has no `inline`: the functions have internal linkage here, and a file that uses only
// some of them must not warn of the others.
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "shared/density_ramp.glsl"
#include "shared/depth_slice_decode.glsl"
#include "shared/view_choice.glsl"
#include "shared/virtual_levels.glsl"
#pragma GCC diagnostic pop
} // namespace

} // namespace shadowlab::glsl
