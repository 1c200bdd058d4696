#include "WallTicker.h"

namespace shadowlab {

namespace {

constexpr int kTickIntervalMs = 33;

} // namespace

WallTicker::WallTicker(QObject* parent) : QObject(parent)
{
    m_timer.setInterval(kTickIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, [this] { emit ticked(double(m_clock.restart()) * 1e-3); });
}

void WallTicker::setRunning(bool running)
{
    if (running && !m_timer.isActive()) {
        m_clock.start();
        m_timer.start();
    } else if (!running) {
        m_timer.stop();
    }
}

} // namespace shadowlab
