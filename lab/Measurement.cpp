#include "Measurement.h"

#include "RayTracer.h"
#include "Renderer.h"
#include "SceneLibrary.h"
#include "SceneSupply.h"
#include "ShadowReference.h"
#include "ShadowTechnique.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace shadowlab {

AccuracyResult measureAccuracy(AccuracyMeter& meter, Renderer& renderer, const Settings& settings, QSize size,
                               const std::function<void(double)>& progress, TexelDensity* density)
{
    supplyScene(renderer, settings);
    const VisibilityBuffer buffer = renderer.renderVisibility(settings, size);
    if (density != nullptr)
        *density = !settings.shadow.enabled ? TexelDensity{}
            : settings.shadow.virtualMap && renderer.virtualMap()
            ? measureVirtualTexelDensity(buffer, *renderer.virtualMap())
            : measureTexelDensity(buffer, renderer.shadowViews(), renderer.lightFrame(), settings.map.size);
    return meter.measure(buffer, *renderer.scene(), renderer.lightFrame(), settings, progress);
}

FrameCounts countFrames(HeadlessRenderer& headless, const Settings& settings, QSize size, double timeStep)
{
    Renderer& renderer = headless.renderer();
    // A scene playing with the light still counts a frame of it, a step after one drawn whole:
    // what a cache leaves out is not counted.
    Settings counted = settings;
    if (timeStep > 0.0) {
        renderer.invalidateShadowMap();
        headless.renderFrame(settings, size, TimingMode::Finish);
        counted.animation.time += timeStep;
    } else {
        renderer.invalidateShadowMap();
    }
    renderer.setCounting(true);
    try {
        headless.renderFrame(counted, size, TimingMode::Finish);
    } catch (...) {
        renderer.setCounting(false);
        throw;
    }
    renderer.setCounting(false);
    FrameCounts counts = renderer.lastFrame().counts;
    // A map drawn into slices (map.slices) is cleared once in that many passes: a pass clears that
    // share of the map of one view, and of what a pass draws into a point light's faces (the
    // first of a cycle clears, in each face, what the cycle drew: about that, as the light
    // moves).
    const ShadowMap& map = renderer.shadowMap();
    const FramePlan& plan = renderer.lastPlan();
    const bool depthMap = plan.shadows && !plan.virtualMap && !plan.moments;
    if (depthMap && renderer.lastFrame().shadowPassRendered && map.slice().scale < 1.0) {
        std::int64_t cleared = std::int64_t(map.width()) * map.height();
        if (map.columns() * map.rows() > 1) {
            cleared = 0;
            for (int row = 0; row < map.rows(); ++row) {
                for (int column = 0; column < map.columns(); ++column) {
                    const QRect drawn = map.written().written(QRect(column * map.size(), row * map.size(), map.size(), map.size()));
                    cleared += std::int64_t(drawn.width()) * drawn.height();
                }
            }
        }
        counts.clearedTexels = cleared / std::max(1, plan.slices);
    }
    return counts;
}

namespace {

// The counts of `run`'s configuration, from its camera path's first camera.
void countRun(TimedRun& run, QSize size)
{
    Settings settings = run.settings;
    if (!run.cameraPath.empty())
        settings.camera = run.cameraPath.front();
    run.samples.counts = countFrames(*run.headless, settings, size, run.moving ? 0.0 : run.timeStep);
}

// One frame of `run`, the `index`th of its camera path.
void renderRunFrame(TimedRun& run, QSize size, int index)
{
    HeadlessRenderer& h = *run.headless;
    if (run.moving)
        h.renderer().invalidateShadowMap();
    if (!run.cameraPath.empty() || run.timeStep > 0.0) {
        Settings moved = run.settings;
        if (!run.cameraPath.empty())
            moved.camera = run.cameraPath[std::size_t(index) % run.cameraPath.size()];
        moved.animation.time += run.timeStep * index;
        h.renderFrame(moved, size, TimingMode::Finish);
    } else {
        h.renderFrame(run.settings, size, TimingMode::Finish);
    }
}

void recordFrame(FrameSamples& s, const FrameStats& f)
{
    s.last = f;
    if (f.shadowPassRendered) {
        s.shadow.push_back(f.shadowPassMs);
        s.shadowWall.push_back(f.shadowPassWallMs);
        if (f.blurPassWallMs > 0.0)
            s.blurWall.push_back(f.blurPassWallMs);
        ++s.shadowPassesRun;
        s.shadowMapClears += f.shadowMapCleared;
        s.shadowDraws = f.shadowDraws;
    }
    if (s.viewWall.size() < f.viewRendered.size()) {
        s.viewWall.resize(f.viewRendered.size());
        s.viewPassesRun.resize(f.viewRendered.size(), 0);
        s.viewDraws.resize(f.viewRendered.size(), 0);
    }
    for (std::size_t v = 0; v < f.viewRendered.size(); ++v) {
        if (f.viewRendered[v]) {
            s.viewWall[v].push_back(f.viewWallMs[v]);
            ++s.viewPassesRun[v];
            s.viewDraws[v] = f.viewDraws[v];
        }
    }
    if (f.virtualMap) {
        s.pagesDrawn.push_back(f.virtualPages.drawn);
        s.pagesResident.push_back(f.virtualPages.resident);
    }
    s.lit.push_back(f.litPassMs);
    s.litWall.push_back(f.litPassWallMs);
    s.wall.push_back(f.frameWallMs);
    s.outsideWall.push_back(f.frameWallMs - (f.shadowPassRendered ? f.shadowPassWallMs : 0.0) - f.litPassWallMs);
}

} // namespace

void timeInterleaved(std::vector<TimedRun>& runs, QSize size, int warmup, int frames, const std::function<void(double)>& progress)
{
    for (int i = 0; i < warmup + frames; ++i) {
        for (TimedRun& run : runs) {
            if (run.settleFirst)
                run.headless->renderFrame(run.settings, size, TimingMode::Finish);
            renderRunFrame(run, size, i);
            if (i >= warmup)
                recordFrame(run.samples, run.headless->renderer().lastFrame());
        }
        if (progress)
            progress(double(i + 1) / double(warmup + frames));
    }
    for (TimedRun& run : runs)
        countRun(run, size);
}

namespace {

// What a run allocates for its maps: runs that agree share the renderer's textures, so a switch
// between them reallocates nothing (a 2048 moments map and its scratch are 128 MB to fault in).
auto storageOrder(const Settings& s)
{
    const ShadowMapKind kind = shadowTechnique(s.filter.mode).map;
    return std::make_tuple(int(kind), int(s.moments.format), s.moments.mipmaps, s.map.size, int(s.map.format), int(s.light.type), s.shadow.cascades,
                           s.shadow.virtualMap, s.shadow.virtualPool);
}

} // namespace

void timeUntilSteady(std::vector<TimedRun>& runs, QSize size, int warmup, const SteadyTiming& rule, const std::function<void(double)>& progress)
{
    const int batch = std::max(1, rule.batch);
    std::vector<int> rendered(runs.size(), 0);      // frames of each run's camera path so far
    std::vector<bool> steady(runs.size(), false);
    // Each round visits every run once (so a slow spell still lands on all alike), runs that
    // share their maps' storage one after another.
    std::vector<std::size_t> order(runs.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return storageOrder(runs[a].settings) < storageOrder(runs[b].settings); });
    for (bool first = true; std::find(steady.begin(), steady.end(), false) != steady.end(); first = false) {
        for (const std::size_t r : order) {
            if (steady[r])
                continue;
            TimedRun& run = runs[r];
            // The first visit's warm-up takes the switch as well.
            if (first && warmup > 0) {
                for (int i = 0; i < warmup; ++i)
                    renderRunFrame(run, size, rendered[r]++);
            } else if (run.settleFirst) {
                run.headless->renderFrame(run.settings, size, TimingMode::Finish);
            }
            for (int i = 0; i < batch && int(run.samples.wall.size()) < rule.maximum; ++i) {
                renderRunFrame(run, size, rendered[r]++);
                recordFrame(run.samples, run.headless->renderer().lastFrame());
            }
            steady[r] = timingIsSteady(run.samples.wall, rule);
            if (steady[r])
                countRun(run, size);
        }
        if (progress) {
            double done = 0.0;
            for (std::size_t r = 0; r < runs.size(); ++r)
                done += steady[r] ? 1.0 : std::min(1.0, double(runs[r].samples.wall.size()) / std::max(1, rule.maximum));
            progress(done / double(runs.size()));
        }
    }
}

namespace {

// The smallest image of `size`'s aspect ratio (640x360: 16x9). The light's fit reads the
// aspect, never the pixels, so the maps placed for it are those of `size`, for far less
// rendering and read-back.
QSize sameAspect(QSize size)
{
    const int divisor = std::gcd(size.width(), size.height());
    return divisor > 0 ? size / divisor : size;
}

// Renders `still` at `size` with the light fitted to each camera of `path` in turn, keeping
// the frames when asked; returns in how many steps the light's maps moved.
int walkPath(Renderer& renderer, const Settings& still, const std::vector<CameraSettings>& path, QSize size, std::vector<VisibilityBuffer>* frames)
{
    // Whether the maps moved at all: every view's shadow matrix, frame to frame.
    const auto matrices = [&renderer] {
        std::vector<glm::dmat4> m{renderer.lightFrame().shadowMatrix};
        for (const LightFrame& frame : renderer.shadowViews().frames)
            m.push_back(frame.shadowMatrix);
        return m;
    };
    std::vector<glm::dmat4> last;
    int moves = 0;
    supplyScene(renderer, still);
    try {
        for (const CameraSettings& camera : path) {
            renderer.setFitCamera(camera);
            VisibilityBuffer frame = renderer.renderVisibility(still, size);
            if (frames) {
                // Flicker reads the shadow term alone: the light terms of every frame held
                // would nearly double what the walk keeps in memory.
                frame.ambientLight = {};
                frame.directLight = {};
                frames->push_back(std::move(frame));
            }
            const std::vector<glm::dmat4> now = matrices();
            moves += !last.empty() && now != last ? 1 : 0;
            last = now;
        }
    } catch (...) {
        renderer.setFitCamera(std::nullopt);
        throw;
    }
    renderer.setFitCamera(std::nullopt);
    return moves;
}

} // namespace

FlickerResult measureFlicker(Renderer& renderer, const Settings& settings, const std::vector<CameraSettings>& path, QSize size, FlickerWalk walk)
{
    Settings still = settings;
    if (!path.empty())
        still.camera = path.front();
    std::vector<VisibilityBuffer> frames;
    // Maps that stay put over the walk draw the same shadow term at the same points every
    // frame, so nothing flickers: one frame at `size` counts the receivers, and the walk is
    // rendered small.
    if (walk == FlickerWalk::WhereMapsMove && path.size() > 1 && sameAspect(size) != size
        && walkPath(renderer, still, path, sameAspect(size), nullptr) == 0) {
        walkPath(renderer, still, {path.front()}, size, &frames);
        FlickerResult result = measureFlicker(frames);
        result.frames = int(path.size());
        return result;
    }
    frames.reserve(path.size());
    const int moves = walkPath(renderer, still, path, size, &frames);
    FlickerResult result = measureFlicker(frames);
    result.mapMoves = moves;
    return result;
}

FlickerResult measureTimeFlicker(Renderer& renderer, const Settings& settings, const std::vector<double>& times, QSize size)
{
    std::vector<VisibilityBuffer> frames;
    std::vector<std::vector<float>> references;
    std::unique_ptr<RayTracer> tracer;
    ReferenceOptions options;
    options.area = false;
    supplyScene(renderer, settings);
    for (double t : times) {
        Settings at = settings;
        at.animation.time = t;
        frames.push_back(renderer.renderVisibility(at, size));
        if (!tracer)
            tracer = std::make_unique<RayTracer>(*renderer.scene(), frames.back().cameraPosition);
        else
            tracer->pose(*renderer.scene());
        references.push_back(traceReference(*tracer, frames.back(), renderer.lightFrame(), options).hard);
    }
    return measureTimeFlicker(frames, references);
}

std::vector<CameraSettings> subTexelPath(Renderer& renderer, const Settings& settings, QSize size, int frames, double texels)
{
    supplyScene(renderer, settings);
    renderer.renderVisibility(settings, sameAspect(size));
    const double texel = renderer.lastFrame().texelWorldSize;
    return cameraPath(settings.camera, frames, texel * texels);
}

} // namespace shadowlab
