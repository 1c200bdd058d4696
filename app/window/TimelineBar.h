#pragma once

#include "WallTicker.h"

#include <QToolBar>

class QAction;
class QLabel;
class QSlider;

namespace shadowlab {

// The scene's clock under the views: play and pause, a scrubber over the clip, the time and the
// clip's length. It shows scene.time and scene.play and asks for changes; the window owns the
// settings, and runs the clock (ticked) while the scene plays. A still scene greys it out and
// says why.
class TimelineBar : public QToolBar {
    Q_OBJECT

public:
    explicit TimelineBar(QWidget* parent = nullptr);

    // The clip of the scene shown, in seconds (0: nothing moves), and where the clock stands.
    void show(double clipLength, double time, bool playing);
    bool isScrubbing() const { return m_scrubbing; }

signals:
    void playToggled(bool play);
    void scrubStarted();
    void scrubbed(double time);     // while the scrubber is dragged, or clicked
    void scrubFinished();
    void ticked(double wallSeconds);    // while playing

private:
    static constexpr int kSteps = 1000;

    WallTicker m_ticker;
    QAction* m_play = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_time = nullptr;
    double m_clip = 0.0;
    bool m_scrubbing = false;
};

} // namespace shadowlab
