#pragma once

#include "BiasTuner.h"
#include "Flicker.h"

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
// timing loop that `report` and `bench` use.
class AccuracyController : public QObject {
    Q_OBJECT

public:
    struct Measurement {
        Settings settings;
        ErrorMetrics hard;
        ErrorMetrics area;
        double areaNoiseFloor = 0.0;
        QImage errors;              // false shadow / false light over the measured frame
        FlickerResult flicker;      // over a sub-texel camera walk (Measurement.h)
    };

    struct SweepPoint {
        QString label;              // what differs from the current settings
        Settings settings;
        double frameMs = 0.0;
        double misclassifiedPercent = 0.0;
    };

    explicit AccuracyController(QObject* parent = nullptr);
    ~AccuracyController() override;

    void setSettings(const Settings& settings);
    const Settings& settings() const { return m_settings; }
    void setViewSize(QSize size);
    // The view size scaled down to at most kMaxMeasureSide px per side, keeping the aspect.
    QSize measureSize() const;
    // n² rays per pixel for the area reference; more is smoother and slower.
    void setAreaSamplesPerAxis(int samples);
    int areaSamplesPerAxis() const { return m_areaSamplesPerAxis; }

    // Whether a reference trace or a sweep is under way.
    bool isBusy() const;

    // Measures the current view (tracing the reference first when the cache does not hold it).
    void compare();
    // The same, then the sweep around the current settings.
    void sweep();
    // Searches the bias with the fewest misclassified pixels over several light directions
    // (BiasTuner), between events; tuning() holds the result when it finishes.
    void tuneBias();
    void cancel();
    const std::optional<BiasTuning>& tuning() const { return m_tuning; }

    const std::optional<Measurement>& measurement() const { return m_measurement; }
    // The measurement is of the current settings at the current measure size.
    bool measurementIsCurrent() const;
    int referenceSamplesPerPixel() const { return m_reference.samplesPerPixel; }
    double lastRaysPerSecond() const { return m_lastRaysPerSecond; }
    bool lastReferenceReused() const { return m_lastReferenceReused; }
    const std::vector<SweepPoint>& sweepPoints() const { return m_sweepPoints; }

    static constexpr int kMaxMeasureSide = 960;
    static constexpr int kTimedFrames = 5;

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

    // A reference trace running on m_tracePool; the capture it belongs to waits here.
    struct PendingTrace {
        ReferenceKey key;
        Settings settings;
        std::shared_ptr<const VisibilityBuffer> buffer;
        std::shared_ptr<std::atomic<bool>> cancel;
        bool thenSweep = false;
    };

    void startMeasurement(bool thenSweep);
    void traceFinished();
    void measure(const Settings& settings, const VisibilityBuffer& buffer);
    void startSweep();
    void sweepStep();
    void finishSweep(const QString& message);
    void tuneStep();
    HeadlessRenderer& headless();
    void setStatus(const QString& text, bool error = false);
    FlickerResult m_flicker;        // of the settings being measured, taken before the trace

    Settings m_settings;
    QSize m_viewSize;
    int m_areaSamplesPerAxis = 8;   // 64 rays/px: a quarter of `report`'s default, quick enough to wait for

    std::unique_ptr<HeadlessRenderer> m_headless;
    std::unique_ptr<BiasTuner> m_tuner;     // while tuning
    bool m_tuneCancelled = false;
    std::optional<BiasTuning> m_tuning;
    std::optional<ReferenceKey> m_referenceKey;
    ReferenceVisibility m_reference;
    double m_lastRaysPerSecond = 0.0;
    bool m_lastReferenceReused = false;
    std::optional<Measurement> m_measurement;

    QThreadPool m_tracePool;        // the trace itself fans out on the global pool
    QFutureWatcher<TraceOutcome> m_traceWatcher;
    std::optional<PendingTrace> m_pending;

    std::vector<SweepPoint> m_sweepPlan;    // the configurations, times still zero
    std::vector<SweepPoint> m_sweepPoints;  // those measured so far
    QStringList m_sweepSkipped;             // labels and reasons of those that failed
    QSize m_sweepSize;                      // the measure size when the sweep started
    std::size_t m_sweepNext = 0;
    bool m_sweeping = false;
    bool m_sweepCancelled = false;
};

} // namespace shadowlab
