#pragma once

#include "LightMath.h"
#include "ShadowViews.h"

#include <vector>

namespace shadowlab {

// The views of a light with several maps (cascades, cube faces) as the passes use them: the
// fitted set and one light frame per view, whose matrices place it in its own tile.
struct ShadowViewFrames {
    ShadowViewSet set;
    std::vector<LightFrame> frames;     // one per set.views entry
    CameraFrame camera;                 // the camera the views were fitted to (cascades pick by its view depth)
};

} // namespace shadowlab
