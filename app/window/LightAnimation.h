#pragma once

#include "WallTicker.h"

namespace shadowlab {

// Animate Light: how far the lights turn around the vertical through their targets, tick by
// tick, at a speed in degrees per second of wall-clock time.
class LightAnimation : public QObject {
    Q_OBJECT

public:
    explicit LightAnimation(QObject* parent = nullptr);

    void setRunning(bool running) { m_ticker.setRunning(running); }
    bool isRunning() const { return m_ticker.isRunning(); }
    double speed() const { return m_speed; }
    void setSpeed(double degreesPerSecond) { m_speed = degreesPerSecond; }

signals:
    void turned(double radians);

private:
    WallTicker m_ticker;
    double m_speed = 30.0;     // degrees per second
};

} // namespace shadowlab
