#include "LightAnimation.h"

#include <glm/trigonometric.hpp>

namespace shadowlab {

namespace {

constexpr int kAnimationIntervalMs = 33;

} // namespace

LightAnimation::LightAnimation(QObject* parent) : QObject(parent)
{
    m_timer.setInterval(kAnimationIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        const double seconds = double(m_clock.restart()) * 1e-3;
        emit turned(glm::radians(m_speed * seconds));
    });
}

void LightAnimation::setRunning(bool running)
{
    if (running && !m_timer.isActive()) {
        m_clock.start();
        m_timer.start();
    } else if (!running) {
        m_timer.stop();
    }
}

} // namespace shadowlab
