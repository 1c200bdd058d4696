#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace shadowlab {

// Animate Light: a tick about 30 times a second that says how far the lights turn around the
// vertical through their targets, by elapsed time, not by tick, so the speed holds when frames
// are slow.
class LightAnimation : public QObject {
    Q_OBJECT

public:
    explicit LightAnimation(QObject* parent = nullptr);

    void setRunning(bool running);
    bool isRunning() const { return m_timer.isActive(); }
    double speed() const { return m_speed; }
    void setSpeed(double degreesPerSecond) { m_speed = degreesPerSecond; }

signals:
    void turned(double radians);

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_speed = 30.0;     // degrees per second
};

} // namespace shadowlab
