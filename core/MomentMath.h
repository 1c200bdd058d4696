#pragma once

#include "Settings.h"

namespace shadowlab {

// The widest moments blur, in texels (moments.blur).
constexpr int kMaxMomentBlur = 31;

// The exponents a moment technique warps depth with, after clamping to what its format can hold.
struct MomentWarp {
    double positive = 0.0;  // esm, evsm2, evsm4: exp(positive * d)
    double negative = 0.0;  // evsm4: -exp(-negative * d)
};

// Whether `mode` reads a moments map (its row's map kind in the technique table).
bool isMomentTechnique(FilterMode mode);

// The largest exponent whose warp `mode` stores in `format` without overflowing: evsm stores
// exp(2c) (its second moment), esm exp(c), over depths in [-1, 1] (evsm) or [0, 1] (esm).
// 16-bit float holds at most 65504: c <= 5.54 for evsm and 11.08 for esm; 32-bit float c <= 44.3
// and 88.7. Zero for techniques without a warp.
double maxExponent(FilterMode mode, MomentFormat format);

// The settings' exponents clamped by maxExponent().
MomentWarp momentWarp(const Settings& settings);

// The widest blur moments.blur_at=auto applies in the lookup: (5 + 1)² / 4 = 9 bilinear reads a
// pixel, fewer than the 2 × 5 of a blur pass for each texel of the map.
constexpr int kWidestLookupBlur = 5;

// Where the settings' blur runs (moments.blur_at, auto resolved): in the lookup or as a pass
// over the map. Lookup with no blur to apply, or where the map has mipmaps or is read
// anisotropically (a footprint the kernel's fixed taps do not follow), is the map's.
bool blursInLookup(const Settings& settings);
// The width of the blur pass over the map: moments.blur, or 0 where the lookup applies it.
int mapBlurWidth(const Settings& settings);
// The radius the lookup's blur reads around its texel, 0 for none (moments.blur_at).
int lookupBlurRadius(const Settings& settings);

} // namespace shadowlab
