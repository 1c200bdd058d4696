#pragma once

#include "FrameStats.h"

#include <QString>

namespace shadowlab {

// What light.warp did in a frame, in the user's words (the render command's output, the
// window's map tooltip): empty where no warp was asked for.
QString warpStatusText(const FrameStats& stats);

} // namespace shadowlab
