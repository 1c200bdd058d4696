#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace shadowlab {

// A tick about 30 times a second that says how much wall-clock time passed since the last one,
// so what it drives moves by elapsed time, not by tick, and keeps its speed when frames are slow.
class WallTicker : public QObject {
    Q_OBJECT

public:
    explicit WallTicker(QObject* parent = nullptr);

    void setRunning(bool running);
    bool isRunning() const { return m_timer.isActive(); }

signals:
    void ticked(double seconds);

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace shadowlab
