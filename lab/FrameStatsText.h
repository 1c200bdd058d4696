#pragma once

#include "FrameStats.h"

#include <QString>

namespace shadowlab {

// What light.warp did in a frame, in the user's words (the render command's output, the
// window's map tooltip): empty where no warp was asked for.
QString warpStatusText(const FrameStats& stats);
// What a virtual shadow map's pages did in a frame ("virtual map: 212 pages requested, 212
// resident of 900, 12 drawn"), with a warning where the pool coarsened requests; empty where
// shadow.virtual is off.
QString virtualMapStatusText(const FrameStats& stats);

} // namespace shadowlab
