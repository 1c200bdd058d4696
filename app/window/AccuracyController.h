#pragma once

#include "BiasTuner.h"
#include "Flicker.h"
#include "FrameStats.h"
#include "LightMath.h"
#include "Scene.h"

#include "Settings.h"
#include "ShadowMetrics.h"
#include "ShadowReference.h"
#include "VisibilityBuffer.h"

#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <QStringList>
#include <QThreadPool>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace shadowlab {

class HeadlessRenderer;

// What the accuracy dock shows, without widgets: measures the current view against the
// ray-traced reference (traced off the GUI thread on its own offscreen renderer, cached while
// scene, camera, size and light placement stay the same), and sweeps variations of the
// current settings for error against frame time, through the one compare function and the one
// timing loop that `report` and `bench` use. In compare mode it holds both sides and measures
// them over the same pixels; the sweep and the bias tuning work on the selected side.
class AccuracyController : public QObject {
    Q_OBJECT

public:
    struct Measurement {
        Settings settings;
        ErrorMetrics hard;
        ErrorMetrics area;
        double dssim = 0.0;         // of the frame, against it shaded with the hard reference (AccuracyResult::ssim)
        double areaNoiseFloor = 0.0;
        int referenceSamplesPerPixel = 0;   // rays per pixel of the area reference
        QImage errors;              // false shadow / false light over the measured frame
        QImage heat;                // |V - V_ref| over it
        FlickerResult flicker;      // over a sub-texel camera walk (Measurement.h)
        FrameCounts counts;         // what a shadow and a lit pass ask of any GPU, at the measured size
    };

    struct SweepPoint {
        QString label;              // what differs from the current settings
        Settings settings;
        double frameMs = 0.0;
        double misclassifiedPercent = 0.0;
        QString visiblyWrong;       // why its picture is visibly wrong (ReportAnalysis.h), or empty
    };

    explicit AccuracyController(QObject* parent = nullptr);
    ~AccuracyController() override;

    // One side: what the scene view shows.
    void setSettings(const Settings& settings);
    // Compare mode: both sides (A first) and the one the sweep and the tuning work on. A side
    // whose settings change keeps its measurement, greyed as stale, until measured again.
    void setSides(const std::vector<Settings>& sides, std::size_t selected);
    // The selected side's settings.
    const Settings& settings() const { return m_sides[m_selected]; }
    const Settings& sideSettings(std::size_t side) const { return m_sides[side]; }
    std::size_t sideCount() const { return m_sides.size(); }
    std::size_t selectedSide() const { return m_selected; }
    void setViewSize(QSize size);
    // The view size scaled down to at most kMaxMeasureSide px per side, keeping the aspect.
    QSize measureSize() const;
    // n² rays per pixel for the area reference; more is smoother and slower.
    void setAreaSamplesPerAxis(int samples);
    int areaSamplesPerAxis() const { return m_areaSamplesPerAxis; }

    // Whether a reference trace or a sweep is under way.
    bool isBusy() const;

    // Measures the current view of every side (tracing a reference first when the cache does
    // not hold it; sides with the same light placement share one).
    void compare();
    // The same, then the sweep around the current settings.
    void sweep();
    // Searches the bias with the fewest misclassified pixels over several light directions
    // (BiasTuner), between events; tuning() holds the result when it finishes.
    void tuneBias();
    void cancel();
    // The last tuning of the selected side on this scene; tuningFinished() also says it went.
    const std::optional<BiasTuning>& tuning() const { return m_tuning; }

    // The selected side's measurement, or side `side`'s.
    const std::optional<Measurement>& measurement() const { return m_measurements[m_selected]; }
    const std::optional<Measurement>& measurement(std::size_t side) const { return m_measurements[side]; }
    // The measurement is of that side's current settings at the current measure size.
    bool measurementIsCurrent() const { return measurementIsCurrent(m_selected); }
    bool measurementIsCurrent(std::size_t side) const;
    double lastRaysPerSecond() const { return m_lastRaysPerSecond; }
    // How many references the last comparison traced (0: all came from the cache).
    int lastReferencesTraced() const { return m_lastReferencesTraced; }
    bool lastReferenceReused() const { return m_lastReferencesTraced == 0; }
    const std::vector<SweepPoint>& sweepPoints() const { return m_sweepPoints; }

    static constexpr int kMaxMeasureSide = 960;
    static constexpr int kTimedFrames = 5;

    // Drops every result and stops the work under way (a new scene, or the scene's file read
    // again), with the signals that make the dock show their absence.
    void withdrawResults();

signals:
    void busyChanged(bool busy);
    // Progress of the trace or the sweep, `value` of `maximum`.
    void progressChanged(int value, int maximum);
    // Empty when there is nothing to say.
    void statusChanged(const QString& text, bool error);
    void measurementChanged();
    void sweepStarted(QSize size);
    void sweepPointsChanged();
    void tuningFinished();

private:
    // What the worker hands back; exceptions do not cross the thread, their message does.
    struct TraceOutcome {
        ReferenceVisibility reference;
        QString error;
    };

    // One side's capture, waiting for its reference.
    struct Capture {
        std::size_t side = 0;
        Settings settings;
        ReferenceKey key;
        std::shared_ptr<const VisibilityBuffer> buffer;
        FlickerResult flicker;      // taken with the capture, over a sub-texel camera walk
        FrameCounts counts;         // ... and the counts of one frame (countFrames())
        // What the trace needs when the reference is not cached: copies, as the renderer may
        // load another scene while it traces.
        std::shared_ptr<const Scene> scene;
        LightFrame light;
    };

    // Drops the tuning alone (another side selected), with the signals that make the dock
    // show its absence.
    void withdrawTuning();
    void startMeasurement(bool thenSweep);
    // Measures the waiting captures whose reference is cached, and starts the trace of the
    // first one whose is not; then the sweep, when asked for.
    void measureCaptures();
    void traceFinished();
    void measure(const Capture& capture, const ReferenceVisibility& reference);
    // The cached reference for `key`, or null.
    const ReferenceVisibility* cachedReference(const ReferenceKey& key) const;
    void startSweep(const Settings& around);
    void sweepStep();
    void finishSweep(const QString& message);
    void tuneStep();
    HeadlessRenderer& headless();
    void setStatus(const QString& text, bool error = false);

    std::vector<Settings> m_sides{Settings{}};
    std::size_t m_selected = 0;
    QSize m_viewSize;
    int m_areaSamplesPerAxis = 8;   // 64 rays/px: a quarter of `report`'s default, quick enough to wait for

    std::unique_ptr<HeadlessRenderer> m_headless;
    std::unique_ptr<BiasTuner> m_tuner;     // while tuning
    bool m_tuneCancelled = false;
    std::optional<BiasTuning> m_tuning;
    QSize m_tunedSize;                      // the size the tuner measured at
    // The last references traced, newest first: one per side's light placement.
    std::vector<std::pair<ReferenceKey, ReferenceVisibility>> m_references;
    static constexpr std::size_t kCachedReferences = 2;
    double m_lastRaysPerSecond = 0.0;
    int m_lastReferencesTraced = 0;
    std::vector<std::optional<Measurement>> m_measurements{1};

    QThreadPool m_tracePool;        // the trace itself fans out on the global pool
    QFutureWatcher<TraceOutcome> m_traceWatcher;
    std::vector<Capture> m_captures;    // measured in order; the first is being traced while m_tracing
    bool m_tracing = false;
    std::shared_ptr<std::atomic<bool>> m_cancelTrace;
    bool m_thenSweep = false;

    std::vector<SweepPoint> m_sweepPlan;    // the configurations, times still zero
    std::vector<SweepPoint> m_sweepPoints;  // those measured so far
    QStringList m_sweepSkipped;             // labels and reasons of those that failed
    QSize m_sweepSize;                      // the measure size when the sweep started
    ReferenceKey m_sweepKey;                // of the selected side's reference, which the sweep measures against
    std::size_t m_sweepNext = 0;
    bool m_sweeping = false;
    bool m_sweepCancelled = false;
};

} // namespace shadowlab
