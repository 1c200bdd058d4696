#pragma once

#include "ShadowViewFrames.h"
#include "VirtualShadowMap.h"
#include "VisibilityBuffer.h"

#include <vector>

namespace shadowlab {

// How many screen pixels one shadow-map texel covers at the receivers of a measured frame, as
// the texel density view tints them (blue: a texel smaller than a pixel). Each light-facing
// receiver pixel inside its view's map is taken with its right (or left) and lower (or upper)
// neighbour on the same surface: the change of its map texel across one pixel.
struct TexelDensity {
    int counted = 0;            // receiver pixels inside a view's map with neighbours on their surface
    int fine = 0;               // ... whose texel covers at most one pixel
    double medianPixelsPerTexel = 0.0;
    double fineShare() const { return counted > 0 ? double(fine) / counted : 0.0; }
};

// `views` the frame's light views (Renderer::shadowViews()), `light` its light (for a point
// light's faces), `mapSize` texels per view. `perPixel`, where given, gets each pixel's screen
// pixels per texel (NaN where it is not counted), to compare two frames over the same pixels.
TexelDensity measureTexelDensity(const VisibilityBuffer& buffer, const ShadowViewFrames& views, const LightFrame& light, int mapSize,
                                 std::vector<double>* perPixel = nullptr);

// The same for a virtual shadow map (shadow.virtual), at the level each pixel reads: the one
// its density asks for, or the resident one the lookup falls back to.
TexelDensity measureVirtualTexelDensity(const VisibilityBuffer& buffer, const VirtualShadowMap& map, std::vector<double>* perPixel = nullptr);

} // namespace shadowlab
