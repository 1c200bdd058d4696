#pragma once

#include "AccuracyMeter.h"
#include "FrameStats.h"
#include "HeadlessRenderer.h"
#include "SampleStats.h"

#include <functional>
#include <vector>

namespace shadowlab {

// Renders the measuring variant of `settings` at `size` and compares it with the reference
// (traced, or reused from `meter`'s cache). The one path from a renderer to an AccuracyResult,
// for `report`, the accuracy dock and the tests. Throws like Renderer::render() and TraceError.
AccuracyResult measureAccuracy(AccuracyMeter& meter, Renderer& renderer, const Settings& settings, QSize size,
                               const std::function<void(double)>& progress = {});

// What repeated frames of one configuration cost, per pass; GPU and wall times in ms.
struct FrameSamples {
    std::vector<double> shadow, lit, shadowWall, litWall, wall;
    std::vector<double> blurWall;   // of shadowWall, the moments blur and mips (moment techniques only)
    int shadowPassesRun = 0;
    int shadowDraws = 0;
    FrameStats last;
};

// One configuration to time: where it renders, what, and whether the light "moves" (the
// shadow map is redrawn every frame) or stands still (the cached map is reused).
struct TimedRun {
    HeadlessRenderer* headless = nullptr;
    Settings settings;
    bool moving = true;
    // Render an untimed frame of this configuration before each timed one: needed when runs
    // share a renderer, so the switch from the previous run (a map to reallocate) is not timed.
    bool settleFirst = false;
    FrameSamples samples;
};

// The one timing loop, used by `bench`, `report` and the accuracy dock: `warmup` untimed then
// `frames` timed frames of every run, interleaved (one frame of each in turn) so a slow spell
// of a shared machine hits every run alike. With TimingMode::Finish, glFinish between passes.
// `progress` (0..1) is called after each round.
void timeInterleaved(std::vector<TimedRun>& runs, QSize size, int warmup, int frames,
                     const std::function<void(double)>& progress = {});

} // namespace shadowlab
