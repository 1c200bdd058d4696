#include "LightAnimation.h"

#include <glm/trigonometric.hpp>

namespace shadowlab {

LightAnimation::LightAnimation(QObject* parent) : QObject(parent)
{
    connect(&m_ticker, &WallTicker::ticked, this, [this](double seconds) { emit turned(glm::radians(m_speed * seconds)); });
}

} // namespace shadowlab
