#pragma once

#include <vector>

namespace shadowlab {

// When a series of frame times has said what it has to say. The report decides "clearly
// faster" by one row's p90 against another's p10, so what must hold is the median and the
// p10-p90 band, not a frame count: a steady configuration tells them in a few batches, a noisy
// one (a slow spell of a shared machine, a heavy tail) needs more frames, up to a cap.
struct SteadyTiming {
    int batch = 4;          // frames timed per visit of a configuration, >= 1
    int minimum = 8;        // frames before any verdict
    int maximum = 30;       // frames at most, steady or not
    // Steady: the last batch moved none of median, p10 and p90 by more than this share of the
    // p10-p90 band of all frames (the summary has stopped changing within its own spread)...
    double bandTolerance = 0.1;
    // ...or by more than this share of the median: a move no reader of a time can see.
    double medianTolerance = 0.03;
};

// Whether `samples` (in the order timed, the newest batch last) are enough under `rule`.
bool timingIsSteady(const std::vector<double>& samples, const SteadyTiming& rule);

} // namespace shadowlab
