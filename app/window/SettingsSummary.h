#pragma once

#include "Settings.h"

#include <QDateTime>
#include <QString>

namespace shadowlab {

// One line that tells two techniques apart at a glance: "pcf 3×3 · slope 0.02 · min 0.001 · 2048² ortho".
QString settingsSummary(const Settings& settings);

// "2048²": the size of a square map.
QString squareSize(int side);

// A screenshot's default file name: the date, then what is on screen, e.g.
// "shadowlab-2026-11-22-1530-seed-pcf3-2048.png". Only [a-z0-9-.] so it is safe everywhere.
// The depth pane's caption: the light's projection and what its map holds (depth in its
// format, or a moment technique's moments), or that shadows are off.
QString shadowMapSummary(const Settings& settings);
QString screenshotFileName(const Settings& settings, const QDateTime& when);

} // namespace shadowlab
