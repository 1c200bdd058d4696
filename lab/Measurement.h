#pragma once

#include "AccuracyMeter.h"
#include "Flicker.h"
#include "FrameStats.h"
#include "HeadlessRenderer.h"
#include "SampleStats.h"
#include "SteadyTiming.h"
#include "TexelDensity.h"

#include <functional>
#include <vector>

namespace shadowlab {

// Renders the measuring variant of `settings` at `size` and compares it with the reference
// (traced, or reused from `meter`'s cache). The one path from a renderer to an AccuracyResult,
// for `report`, the accuracy dock and the tests. Throws like Renderer::render() and TraceError.
// With `density`, the frame's texel density (TexelDensity.h) goes there too.
AccuracyResult measureAccuracy(AccuracyMeter& meter, Renderer& renderer, const Settings& settings, QSize size,
                               const std::function<void(double)>& progress = {}, TexelDensity* density = nullptr);

// What repeated frames of one configuration cost, per pass; GPU and wall times in ms.
struct FrameSamples {
    std::vector<double> shadow, lit, shadowWall, litWall, wall;
    std::vector<double> blurWall;   // of shadowWall, the moments blur and mips (moment techniques only)
    // Per frame, its wall time less its shadow and lit passes': the CPU's own work (the fit, the
    // reach, uploads) and any other pass the settings add (sdsm's depth, contact shadows' depth).
    std::vector<double> outsideWall;
    int shadowPassesRun = 0;
    int shadowMapClears = 0;    // of those, the passes that cleared the map (map.slices)
    int shadowDraws = 0;
    // shadow.virtual: pages drawn and resident, every frame.
    std::vector<double> pagesDrawn, pagesResident;
    FrameStats last;
    // Lights with several views: per view, wall ms of the frames that drew it, and how many did.
    std::vector<std::vector<double>> viewWall;
    std::vector<int> viewPassesRun;
    std::vector<int> viewDraws;         // casters drawn the last time each view was drawn
    // What one shadow pass and one lit pass of the configuration ask of any GPU, counted in a
    // frame of their own after the timed ones (countFrames()).
    FrameCounts counts;
};

// What a frame of `settings` at `size` asks of any GPU, its shadow pass drawn (FrameCounts):
// counted in a frame of its own, since the counting queries slow a software rasteriser's
// frame. A map drawn into slices clears its share of the cycle's one clear. With `timeStep`,
// the scene playing with the light still: the frame `timeStep` after one drawn whole, what a
// shadow.cache does a frame. Throws like render().
FrameCounts countFrames(HeadlessRenderer& headless, const Settings& settings, QSize size, double timeStep = 0.0);

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
    // A moving camera: frame i (warm-up included) uses cameraPath[i % size]; empty: still.
    std::vector<CameraSettings> cameraPath;
    // The scene playing: frame i is at settings.animation.time + i * timeStep seconds; 0: still.
    double timeStep = 0.0;
};

// The one timing loop, used by `bench`, `report` and the accuracy dock: `warmup` untimed then
// `frames` timed frames of every run, interleaved (one frame of each in turn) so a slow spell
// of a shared machine hits every run alike. With TimingMode::Finish, glFinish between passes.
// `progress` (0..1) is called after each round.
void timeInterleaved(std::vector<TimedRun>& runs, QSize size, int warmup, int frames,
                     const std::function<void(double)>& progress = {});

// `report`'s timing: each run visited in turn, as in timeInterleaved(), but for a batch of
// frames a visit (`rule.batch`, after one untimed frame that takes the switch from the run
// before, or on the first visit `warmup` untimed frames), until its frame times are steady under `rule`
// (SteadyTiming.h). Runs that are steady drop out; the rest go on, up to rule.maximum frames.
// `progress` (0..1) is called after each round.
void timeUntilSteady(std::vector<TimedRun>& runs, QSize size, int warmup, const SteadyTiming& rule,
                     const std::function<void(double)>& progress = {});

// The camera walk flicker is measured over (report and the accuracy dock): frames, and the
// step in texels of the finest map, under a texel, where an unstabilised map shimmers and a
// snapped one should not move at all.
inline constexpr int kFlickerFrames = 8;
inline constexpr double kFlickerStepTexels = 0.37;

// Whether the flicker walk renders every frame at full size even where the light's maps stay
// put (and so cannot flicker), or only where they move.
enum class FlickerWalk { WhereMapsMove, EveryFrame };

// Shimmer of `settings` over `path`: every frame measured from the path's first camera (the
// same pixels, the same world points) while the light's maps are fitted to the path's camera
// of that frame, so any change of the shadow term is the maps' doing. Throws like render().
FlickerResult measureFlicker(Renderer& renderer, const Settings& settings, const std::vector<CameraSettings>& path, QSize size,
                             FlickerWalk walk = FlickerWalk::WhereMapsMove);

// The scene's camera path in steps of `texels` of the light's finest map (its first cascade),
// a fraction for sub-texel motion: what flicker is measured over.
// Flicker over an animation (measureTimeFlicker()): the frames of `settings` at `times`, the camera
// still, each against a hard reference traced at its instant (one tracer, its moving casters
// moved from instant to instant).
FlickerResult measureTimeFlicker(Renderer& renderer, const Settings& settings, const std::vector<double>& times, QSize size);

std::vector<CameraSettings> subTexelPath(Renderer& renderer, const Settings& settings, QSize size, int frames, double texels);

} // namespace shadowlab
