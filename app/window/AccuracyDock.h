#pragma once

#include "FrameTimeHistory.h"
#include "Settings.h"

#include <QDockWidget>
#include <QImage>

#include <array>
#include <optional>
#include <vector>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

class QChartView;

namespace shadowlab {

class AccuracyController;
class AccuracyMetricsPanel;
class SweepChartPanel;

// How wrong the current shadow settings are, next to what they cost. "Compare with reference"
// measures the current view against a ray-traced reference; the sweep plots error against
// frame time for variations of the current settings, and a click on a point applies it. The
// work is the AccuracyController's (on its own offscreen renderer, so the scene views'
// contexts are never touched); this dock is its buttons, progress and status, and two panels:
// the numbers (AccuracyMetricsPanel) and the chart (SweepChartPanel).
class AccuracyDock : public QDockWidget {
    Q_OBJECT

public:
    explicit AccuracyDock(QWidget* parent = nullptr);
    ~AccuracyDock() override;

    // What the scene view shows; a change makes the overlay stale, so it is withdrawn.
    void setSettings(const Settings& settings);
    // Compare mode: both sides, measured together over the same pixels; the sweep and the
    // bias tuning work on the selected one. `b` empty: one side, A.
    void setSides(const Settings& a, const std::optional<Settings>& b, int selected);
    // The scene views' recent frame times (A, then B in compare mode), beside the error.
    void setFrameTimes(const std::vector<FrameTimeHistory::Summary>& sides, bool cpuTime);
    void setViewSize(QSize size);
    // The view size scaled down to at most AccuracyController::kMaxMeasureSide px per side.
    QSize measureSize() const;

    // n² rays per pixel for the area reference; more is smoother and slower.
    void setAreaSamplesPerAxis(int samples);
    int areaSamplesPerAxis() const;

    // Whether a reference trace or a sweep is under way.
    bool isBusy() const;
    // The scene's file was read again (it changed on disk): what was measured of its old
    // contents is withdrawn, and work under way stopped, so no sweep mixes the two.
    void sceneContentsChanged();

    // A model was opened: with "Tune when a model opens" checked (the default, kept between
    // sessions), tune its bias against the reference in the background, at the dock's small
    // size, and ask for the result as one undo step (tunedBiasRequested) when it is clearly
    // better than the model's defaults; the tuning's note says what was chosen and why.
    void tuneForOpenedModel();
    bool tunesOnOpen() const;

signals:
    // The error image over side `side`'s measured frame (0 A, 1 B), or a null image when
    // there is none to show.
    void errorOverlayChanged(int side, const QImage& image);
    // A sweep point was clicked: show these settings.
    void applySettingsRequested(const shadowlab::Settings& settings);
    // The bias tuned when a model opened, to set as one undo step.
    void tunedBiasRequested(const shadowlab::Settings& settings);

private:
    // The compare button, the progress bar with Cancel, and the status line.
    void addMeasureRows(QVBoxLayout* layout);
    // Tune bias, Apply tuned bias, and the tuning's chart and result.
    void addTuningRows(QVBoxLayout* layout);
    void connectController();
    void updateOverlay();
    void updateButtons();
    void showTuning();
    // The settings with the tuning's best bias (a tuning must be there).
    Settings tunedSettings() const;
    void setStatus(const QString& text, bool error = false);

    AccuracyController* m_controller = nullptr;
    std::array<QImage, 2> m_overlays;   // as last emitted, per side

    QPushButton* m_compareButton = nullptr;
    QPushButton* m_cancelButton = nullptr;
    QPushButton* m_tuneButton = nullptr;
    QPushButton* m_applyTuningButton = nullptr;
    QCheckBox* m_tuneOnOpen = nullptr;
    bool m_tuningForOpen = false;           // the tuning under way was started by a model's opening
    QChartView* m_tuningChart = nullptr;   // false shadow against false light of the tuned grid
    QLabel* m_tuningResult = nullptr;      // what the curve says: the best point, or nothing to apply
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    AccuracyMetricsPanel* m_metrics = nullptr;
    SweepChartPanel* m_chart = nullptr;
};

} // namespace shadowlab
