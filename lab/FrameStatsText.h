#pragma once

#include "FrameStats.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace shadowlab {

// What light.warp did in a frame, in the user's words (the render command's output, the
// window's map tooltip): empty where no warp was asked for.
QString warpStatusText(const FrameStats& stats);
// What a virtual shadow map's pages did in a frame ("virtual map: 212 pages requested, 212
// resident of 900, 12 drawn"), with a warning where the pool coarsened requests; empty where
// shadow.virtual is off.
QString virtualMapStatusText(const FrameStats& stats);
// Why the shadow pass drew this frame, and how many of the views ("2 of 6 views redrawn:
// casters moved"); empty when it drew nothing. The status bar and the depth pane say it.
QString redrawStatusText(const FrameStats& stats);
// shadow.cache: how many views (or a virtual map's pages) are cached, stale or drawn and why,
// and the copies' memory ("cache: 3 cached, 1 caster moved · copies 16 MiB"); empty without a cache.
QString cacheStatusText(const FrameStats& stats);

// A count for people: "812", "12.4 k", "4.19 M", "1.07 G"; "n/a" for a count not taken (-1).
QString countText(std::int64_t count);
// Bytes for people: "16 MiB".
QString bytesText(std::int64_t bytes);
// What a frame asked of any GPU (FrameCounts), one line per pass: "shadow pass: 3 draws, 1.2 k
// triangles, 2.10 M samples, 4.19 M texels cleared, map 16 MiB" and "lit pass: 4 draws, ...,
// 0.92 M lookups of 9 taps = 8.29 M taps"; with a blur line for a moments map.
QStringList countsLines(const FrameCounts& counts);
// The same for machines: every count by its name, null where not taken.
QJsonObject countsJson(const FrameCounts& counts);

} // namespace shadowlab
