#pragma once

#include "FrameTimeHistory.h"
#include "Settings.h"

#include <QObject>
#include <QString>

#include <array>
#include <optional>
#include <vector>

class QAction;

namespace shadowlab {

class CompareController;
class SceneView;

// The frame times of each side's view: a rolling window of wall times per settings state (a
// frame of other settings says nothing about these), Measure 100 Frames, and the status bar's
// and the accuracy dock's read-outs of them.
class TimingController : public QObject {
    Q_OBJECT

public:
    static constexpr int kMeasuredFrames = 100;

    TimingController(const CompareController& sides, std::array<SceneView*, 2> views, QObject* parent = nullptr);

    // View → Measure 100 Frames, owned by `owner`: measure(kMeasuredFrames).
    QAction* createMeasureAction(QObject* owner);
    // Redraws the selected side (both in compare mode) `count` times, the shadow pass included.
    void measure(int count);
    // After a frame of `side`'s view; `animated`: the light moves every frame.
    void record(std::size_t side, bool animated);

    // Side A's summary, and side B's in compare mode.
    std::vector<FrameTimeHistory::Summary> summaries() const;
    // Whether the times are CPU time (a software renderer such as llvmpipe).
    bool cpuTime() const;
    QString text(std::size_t side) const;
    // The status bar's: the selected side's, or both and their difference in compare mode.
    QString statusText() const;
    QString toolTip() const;

signals:
    void frameRecorded();
    // What a measurement is doing, and when done what it found, for the status bar.
    void message(const QString& text, int timeoutMs);

private:
    const CompareController& m_sides;
    std::array<SceneView*, 2> m_views;
    QAction* m_measureAction = nullptr;
    std::array<FrameTimeHistory, 2> m_history;  // rolling wall times per side, for the status bar
    std::array<std::optional<Settings>, 2> m_historyState;  // what those frames rendered (no camera)
    int m_measureLeft = 0;      // frames still to draw for Measure 100 Frames
};

} // namespace shadowlab
