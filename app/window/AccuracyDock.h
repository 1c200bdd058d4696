#pragma once

#include "MeasureTarget.h"
#include "Settings.h"
#include "ShadowMetrics.h"
#include "ShadowReference.h"

#include <QDockWidget>
#include <QFutureWatcher>
#include <QImage>
#include <QStringList>
#include <QThreadPool>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QChart;
class QLabel;
class QProgressBar;
class QPushButton;
class QScatterSeries;
class QLogValueAxis;
class QValueAxis;

namespace shadowlab {

class HeadlessRenderer;

// How wrong the current shadow settings are, next to what they cost. "Compare with reference"
// measures the current view against a ray-traced reference (traced off the GUI thread, cached
// while scene, camera, size and light placement stay the same); the sweep plots error against
// frame time for variations of the current settings, and a click on a point applies it.
// Measures on its own offscreen renderer, so the scene views' contexts are never touched.
class AccuracyDock : public QDockWidget {
    Q_OBJECT

public:
    explicit AccuracyDock(QWidget* parent = nullptr);
    ~AccuracyDock() override;

    // What the scene view shows; a change makes the overlay stale, so it is withdrawn.
    void setSettings(const Settings& settings);
    void setViewSize(QSize size);
    // The view size scaled down to at most kMaxMeasureSide px per side, keeping the aspect.
    QSize measureSize() const;

    // n² rays per pixel for the area reference; more is smoother and slower.
    void setAreaSamplesPerAxis(int samples);
    int areaSamplesPerAxis() const { return m_areaSamplesPerAxis; }

    // Whether a reference trace or a sweep is under way.
    bool isBusy() const;

    static constexpr int kMaxMeasureSide = 960;

signals:
    // The error image over the measured frame, or a null image when there is none to show.
    void errorOverlayChanged(const QImage& image);
    // A sweep point was clicked: show these settings.
    void applySettingsRequested(const shadowlab::Settings& settings);

private:
    struct Measurement {
        Settings settings;
        ErrorMetrics hard;
        ErrorMetrics area;
        double areaNoiseFloor = 0.0;
        QImage errors;
    };

    struct SweepPoint {
        QString label;              // what differs from the current settings
        Settings settings;
        double frameMs = 0.0;
        double misclassifiedPercent = 0.0;
    };

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

    QWidget* buildMetricsPanel();
    QWidget* buildChartPanel();

    void compare();
    void sweep();
    void cancel();
    // Captures the current view and measures it, tracing the reference first if the cache
    // does not hold it; then starts the sweep if asked.
    void startMeasurement(bool thenSweep);
    void traceFinished();
    void measure(const Settings& settings, const VisibilityBuffer& buffer);
    void startSweep();
    void sweepStep();
    void finishSweep(const QString& message);
    // Fits the axes to the sweep points and plots them.
    void refreshChart();
    // Where a point sits on the chart: on the log axis, no error sits on its floor.
    QPointF plotted(const SweepPoint& point) const;
    // The sweep point plotted nearest to `point` (chart coordinates), -1 when there are none.
    int sweepPointAt(const QPointF& point) const;
    void pointClicked(const QPointF& point);
    void pointHovered(const QPointF& point, bool state);

    HeadlessRenderer& headless();
    void showMetrics();
    void updateOverlay();
    void updateCurrentMarker();
    void updateButtons();
    void setStatus(const QString& text, bool error = false);

    Settings m_settings;
    QSize m_viewSize;
    int m_areaSamplesPerAxis = 8;   // 64 rays/px: a quarter of `report`'s default, quick enough to wait for

    std::unique_ptr<HeadlessRenderer> m_headless;
    std::optional<ReferenceKey> m_referenceKey;
    ReferenceVisibility m_reference;
    double m_lastRaysPerSecond = 0.0;
    bool m_lastReferenceReused = false;
    std::optional<Measurement> m_measurement;
    QImage m_overlay;               // as last emitted

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

    QPushButton* m_compareButton = nullptr;
    QPushButton* m_sweepButton = nullptr;
    QPushButton* m_cancelButton = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QCheckBox* m_overlayCheck = nullptr;
    QLabel* m_misclassified = nullptr;
    QLabel* m_falseShadow = nullptr;
    QLabel* m_falseLight = nullptr;
    QLabel* m_hardMae = nullptr;
    QLabel* m_hardRmse = nullptr;
    QLabel* m_areaMae = nullptr;
    QLabel* m_areaRmse = nullptr;
    QLabel* m_noiseFloor = nullptr;
    QLabel* m_referenceInfo = nullptr;
    QChart* m_chart = nullptr;
    QScatterSeries* m_variations = nullptr;
    QScatterSeries* m_current = nullptr;
    QValueAxis* m_timeAxis = nullptr;
    QLogValueAxis* m_errorAxis = nullptr;
    QLabel* m_pointInfo = nullptr;
};

} // namespace shadowlab
