#pragma once

#include "VisibilityBuffer.h"

#include <vector>

namespace shadowlab {

// Shimmer: how much the shadow term at fixed receiver points changes from one frame to the
// next while only the camera the light is fitted to moves (the scene, the light and the points
// measured stay put, so every change is the shadow map's doing, none is real).
struct FlickerResult {
    double flicker = 0.0;       // share of receiver pixels whose visibility flips (crosses 0.5) between consecutive frames, mean over pairs
    double worstPair = 0.0;     // the largest share of one pair
    double meanChange = 0.0;    // mean |change of visibility| per receiver pixel and pair (soft filters flicker by degrees)
    int frames = 0;
    int pixels = 0;             // receiver pixels facing the light in the first frame
    // Steps of the walk in which the light's maps moved. 0 with frames > 1: the casters, not the
    // camera, bound the fitted volume here, so this camera cannot show shimmer at all.
    int mapMoves = 0;
    // Flicker is a change between two frames: with fewer (--flicker-frames 0 or 1) it was not
    // measured, which is not "none".
    bool measured() const { return frames > 1; }
};

// Flips between consecutive buffers of the same pixels (same size, same measuring camera);
// only pixels facing the light in both frames count.
FlickerResult measureFlicker(const std::vector<VisibilityBuffer>& frames);

// Over an animation, the camera still: flips between consecutive instants at receiver points
// that did not move, which the hard reference of the same pixels (`references`, one per frame)
// does not have. A shadow that moves because its caster did is no flicker; one that swims, or
// steps over the map's texel grid as its caster glides, is. meanChange is the change the
// reference does not explain.
FlickerResult measureTimeFlicker(const std::vector<VisibilityBuffer>& frames, const std::vector<std::vector<float>>& references);

} // namespace shadowlab
