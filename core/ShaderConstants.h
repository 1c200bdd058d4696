#pragma once

#include <QByteArray>

#include <array>
#include <span>
#include <variant>

namespace shadowlab {

// Numbers that C++ and the shaders both use, each declared once in C++. Every shader program
// gets them all as #defines of the same names (glslConstants(), put ahead of each source by
// renderer/ShaderProgram), so no shader writes one as a literal to be kept in step by hand.
// #defines, not const declarations: those would have to follow a shader's #extension lines.
// Those that belong to a subject stay with it and are listed here too: the virtual map's page
// sizes (VirtualPages.h) and kMaxShadowViews (ShadowViews.h).

using Rgb = std::array<float, 3>;

// pcf64 (shaders/shadow/pcf64.glsl): a box of kPcf64Side² taps at half-texel offsets, the
// outermost kPcf64TapReach texels from the receiver on each axis (its row's tapReach).
inline constexpr int kPcf64Side = 8;
inline constexpr float kPcf64TapReach = float(kPcf64Side - 1) / 2.0f;
// pcss's blocker search (shaders/shadow/pcss.glsl), before the filter's filter.taps.
inline constexpr int kPcssBlockerTaps = 16;
// Entries of the moments blur's weight table (uWeights): the centre and up to 15 a side.
inline constexpr int kMaxBlurWeights = 16;
// Levels of the min/max depth mip that the lit pass's table (uDepthRangeLevel) holds: a
// 2^17-texel map.
inline constexpr int kMaxDepthRangeLevels = 16;
// What the camera's depth of the casters (for contact shadows) holds where no caster is.
inline constexpr float kNoCasterDepth = 1e30f;
// A caster's facet faces away from the light, and shadows itself, where the cosine between its
// normal and the light is below minus this (the lit pass's OWN_FACETS, and the reference's own
// facets in accuracy/ShadowReference.cpp): a facet along the light's rays does not count (a wall
// under a light straight above), whatever the rounding of a normal taken from a pixel's steps.
inline constexpr float kOwnFacetCosine = 1e-3f;

// The overlay colour of each view of the light (shadow.show_cascades): cascades red, green,
// blue, yellow; cube faces add magenta and cyan; a virtual map's levels go round them.
inline constexpr std::array<Rgb, 6> kViewTints{{
    {1.0f, 0.25f, 0.25f},
    {0.25f, 1.0f, 0.25f},
    {0.3f, 0.45f, 1.0f},
    {1.0f, 0.9f, 0.2f},
    {1.0f, 0.3f, 1.0f},
    {0.2f, 1.0f, 1.0f},
}};
// The texel density tint (shaders/ramp.glsl's densityRamp, and the window's legend of it):
// screen pixels per shadow texel, blue under 1, green 1 to 2, yellow about 4, red from 8 up.
inline constexpr Rgb kDensityBlue{0.15f, 0.35f, 0.95f};
inline constexpr Rgb kDensityGreen{0.1f, 0.8f, 0.25f};
inline constexpr Rgb kDensityYellow{0.95f, 0.85f, 0.1f};
inline constexpr Rgb kDensityRed{0.95f, 0.15f, 0.1f};
// The depth view outside the map (lit: clamp to border), a shade lighter than the pane.
inline constexpr Rgb kOutsideMapColour{0.15f, 0.16f, 0.2f};

// A constant as the shaders see it: its C++ name, and its value (an int, a float, a colour or
// an array of colours).
struct ShaderConstant {
    const char* name;
    std::variant<int, float, Rgb, std::span<const Rgb>> value;
};

// Every constant the shaders get.
std::span<const ShaderConstant> shaderConstants();

// `constant` as a GLSL #define of a literal or a constructor of its type: "#define kPcf64Side 8",
// "#define kDensityRed vec3(0.95, 0.15, 0.1)".
QByteArray glslDefine(const ShaderConstant& constant);

// All of them, one #define a line.
QByteArray glslConstants();

// `value` as a GLSL float literal that reads back as exactly `value`: the shortest digits that
// do, with ".0" where they would otherwise read as an int.
QByteArray glslFloat(float value);

} // namespace shadowlab
