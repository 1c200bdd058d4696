#pragma once

#include "Settings.h"

#include <QDateTime>
#include <QString>

namespace shadowlab {

// One line that tells two techniques apart at a glance: "pcf 3×3 · slope 0.02 · min 0.001 · 2048² ortho".
QString settingsSummary(const Settings& settings);

// Compare mode's caption of a side: the settings where `side` differs from `other` first, in
// the keys' own words ("light.fit manual · light.extent 3"; the first few, then how many more),
// then settingsSummary(). Two sides that read alike in the summary still read apart.
QString comparedSummary(const Settings& side, const Settings& other);

// How the light's map is laid out: "2048² ortho", "4 cascades of 2048²", "six 1024² cube faces",
// "virtual map of 900 pages of 128²".
QString mapLayoutSummary(const Settings& settings);

// "2048²": the size of a square map.
QString squareSize(int side);

// The depth pane's caption: what the map is (one map and the light's projection, cascades,
// cube faces, or a virtual map's pool) and what it holds (depth in its format, or a moment
// technique's moments), or that shadows are off.
QString shadowMapSummary(const Settings& settings);

// A screenshot's default file name: the date, then what is on screen, e.g.
// "shadowlab-2026-11-22-1530-seed-pcf3-2048.png". Only [a-z0-9-.] so it is safe everywhere.
QString screenshotFileName(const Settings& settings, const QDateTime& when);

} // namespace shadowlab
