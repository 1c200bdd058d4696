#include "Measurement.h"

#include "Renderer.h"
#include "SceneLibrary.h"

namespace shadowlab {

AccuracyResult measureAccuracy(AccuracyMeter& meter, Renderer& renderer, const Settings& settings, QSize size,
                               const std::function<void(double)>& progress)
{
    const VisibilityBuffer buffer = renderer.renderVisibility(settings, size);
    return meter.measure(buffer, *renderer.scene(), renderer.lightFrame(), settings, progress);
}

void timeInterleaved(std::vector<TimedRun>& runs, QSize size, int warmup, int frames, const std::function<void(double)>& progress)
{
    for (int i = 0; i < warmup + frames; ++i) {
        for (TimedRun& run : runs) {
            HeadlessRenderer& h = *run.headless;
            if (run.settleFirst)
                h.renderFrame(run.settings, size, TimingMode::Finish);
            if (run.moving)
                h.renderer().invalidateShadowMap();
            if (!run.cameraPath.empty()) {
                Settings moved = run.settings;
                moved.camera = run.cameraPath[std::size_t(i) % run.cameraPath.size()];
                h.renderFrame(moved, size, TimingMode::Finish);
            } else {
                h.renderFrame(run.settings, size, TimingMode::Finish);
            }
            if (i < warmup)
                continue;
            const FrameStats& f = h.renderer().lastFrame();
            FrameSamples& s = run.samples;
            s.last = f;
            if (f.shadowPassRendered) {
                s.shadow.push_back(f.shadowPassMs);
                s.shadowWall.push_back(f.shadowPassWallMs);
                if (f.blurPassWallMs > 0.0)
                    s.blurWall.push_back(f.blurPassWallMs);
                ++s.shadowPassesRun;
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
            s.lit.push_back(f.litPassMs);
            s.litWall.push_back(f.litPassWallMs);
            s.wall.push_back(f.frameWallMs);
        }
        if (progress)
            progress(double(i + 1) / double(warmup + frames));
    }
}

FlickerResult measureFlicker(Renderer& renderer, const Settings& settings, const std::vector<CameraSettings>& path, QSize size)
{
    std::vector<VisibilityBuffer> frames;
    frames.reserve(path.size());
    Settings still = settings;
    if (!path.empty())
        still.camera = path.front();
    // Whether the maps moved at all: every view's shadow matrix, frame to frame.
    const auto matrices = [&renderer] {
        std::vector<glm::dmat4> m{renderer.lightFrame().shadowMatrix};
        for (const LightFrame& frame : renderer.shadowViews().frames)
            m.push_back(frame.shadowMatrix);
        return m;
    };
    std::vector<glm::dmat4> last;
    int moves = 0;
    try {
        for (const CameraSettings& camera : path) {
            renderer.setFitCamera(camera);
            frames.push_back(renderer.renderVisibility(still, size));
            // Flicker reads the shadow term alone: the light terms of every frame held would
            // nearly double what the walk keeps in memory.
            frames.back().ambientLight = {};
            frames.back().directLight = {};
            const std::vector<glm::dmat4> now = matrices();
            moves += !last.empty() && now != last ? 1 : 0;
            last = now;
        }
    } catch (...) {
        renderer.setFitCamera(std::nullopt);
        throw;
    }
    renderer.setFitCamera(std::nullopt);
    FlickerResult result = measureFlicker(frames);
    result.mapMoves = moves;
    return result;
}

std::vector<CameraSettings> subTexelPath(Renderer& renderer, const Settings& settings, QSize size, int frames, double texels)
{
    renderer.renderVisibility(settings, size);
    const double texel = renderer.lastFrame().texelWorldSize;
    return cameraPath(settings.camera, frames, texel * texels);
}

} // namespace shadowlab
