#include "TimelineBar.h"

#include <QAction>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace shadowlab {

TimelineBar::TimelineBar(QWidget* parent) : QToolBar(tr("Timeline"), parent)
{
    setObjectName(QStringLiteral("timeline"));
    m_play = addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"));
    m_play->setObjectName(QStringLiteral("timeline.play"));
    m_play->setCheckable(true);
    connect(m_play, &QAction::toggled, this, [this](bool on) { emit playToggled(on); });

    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("timeline.scrubber"));
    m_slider->setRange(0, kSteps);
    m_slider->setMinimumWidth(200);
    addWidget(m_slider);
    connect(m_slider, &QSlider::sliderPressed, this, [this] {
        m_scrubbing = true;
        emit scrubStarted();
    });
    connect(m_slider, &QSlider::sliderReleased, this, [this] {
        m_scrubbing = false;
        emit scrubFinished();
    });
    connect(m_slider, &QSlider::valueChanged, this, [this](int step) {
        // A click on the groove or a key press moves it without a drag: one step of its own.
        if (!m_scrubbing)
            emit scrubStarted();
        emit scrubbed(m_clip * double(step) / kSteps);
        if (!m_scrubbing)
            emit scrubFinished();
    });

    m_time = new QLabel;
    m_time->setObjectName(QStringLiteral("timeline.time"));
    m_time->setMinimumWidth(m_time->fontMetrics().horizontalAdvance(QStringLiteral("000.00 s / 000.00 s")));
    addWidget(m_time);
    connect(&m_ticker, &WallTicker::ticked, this, &TimelineBar::ticked);
    show(0.0, 0.0, false);
}

void TimelineBar::show(double clipLength, double time, bool playing)
{
    m_clip = clipLength;
    const bool moves = clipLength > 0.0;
    for (QWidget* w : {static_cast<QWidget*>(m_slider), static_cast<QWidget*>(m_time)})
        w->setEnabled(moves);
    m_play->setEnabled(moves);
    const QString still = tr("Nothing in this scene moves: give a shape a \"motion\" in a scene file, open a model with a node "
                             "animation, or drive traffic through the city (city+50)");
    m_slider->setToolTip(moves ? tr("scene.time: drag to scrub through the clip") : still);
    m_play->setToolTip(moves ? tr("Play or pause the scene (scene.play)") : still);
    {
        const QSignalBlocker block(m_play);
        m_play->setChecked(playing && moves);
        m_play->setIcon(style()->standardIcon(playing && moves ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        m_play->setText(playing && moves ? tr("Pause") : tr("Play"));
    }
    if (!m_scrubbing) {
        const QSignalBlocker block(m_slider);
        // The end of the clip is its end, not the start of the next loop.
        const double at = moves ? std::fmod(time, clipLength) : 0.0;
        const double within = moves ? (at == 0.0 && time > 0.0 && time <= clipLength ? 1.0 : at / clipLength) : 0.0;
        m_slider->setValue(int(std::lround(std::clamp(within, 0.0, 1.0) * kSteps)));
    }
    m_time->setText(moves ? tr("%1 s / %2 s").arg(std::fmod(time, clipLength), 0, 'f', 2).arg(clipLength, 0, 'f', 2) : tr("still"));
    m_ticker.setRunning(playing && moves && !m_scrubbing);
}

} // namespace shadowlab
