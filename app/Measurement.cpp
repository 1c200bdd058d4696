#include "Measurement.h"

#include "Renderer.h"

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
            h.renderFrame(run.settings, size, TimingMode::Finish);
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
            s.lit.push_back(f.litPassMs);
            s.litWall.push_back(f.litPassWallMs);
            s.wall.push_back(f.frameWallMs);
        }
        if (progress)
            progress(double(i + 1) / double(warmup + frames));
    }
}

} // namespace shadowlab
