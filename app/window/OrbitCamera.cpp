#include "OrbitCamera.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr double kMaxPitch = 89.0;          // degrees above or below the horizon
constexpr double kZoomPerStep = 0.85;       // one wheel notch
constexpr double kMinDistance = 0.05;       // world units
constexpr double kMaxDistance = 1e5;
constexpr double kAboveGround = 0.02;       // of the distance to the target, at least kMinDistance / 2

} // namespace

void OrbitCamera::orbit(double yawDegrees, double pitchDegrees)
{
    const glm::dvec3 offset = m_camera.position - m_camera.target;
    const double distance = glm::length(offset);
    double yaw = std::atan2(offset.x, offset.z);
    double pitch = std::asin(std::clamp(offset.y / distance, -1.0, 1.0));
    yaw -= glm::radians(yawDegrees);
    pitch = std::clamp(pitch + glm::radians(pitchDegrees), glm::radians(-kMaxPitch), glm::radians(kMaxPitch));
    m_camera.position = m_camera.target
        + distance * glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    stayAboveGround();
}

void OrbitCamera::stayAboveGround()
{
    if (!m_ground)
        return;
    const glm::dvec3 offset = m_camera.position - m_camera.target;
    const double distance = glm::length(offset);
    const double floor = *m_ground + std::max(kAboveGround * distance, kMinDistance * 0.5);
    if (m_camera.position.y >= floor || distance <= 0.0)
        return;
    if (m_camera.target.y < floor) {
        // A target under the ground: lift both, the view direction stays.
        const double lift = floor - m_camera.position.y;
        m_camera.position.y += lift;
        m_camera.target.y += lift;
        return;
    }
    // Raise the pitch just enough, keeping the yaw and the distance.
    const double horizontal = std::hypot(offset.x, offset.z);
    const double height = floor - m_camera.target.y;    // <= 0 here, since the camera is below the target's floor
    const double across = std::sqrt(std::max(distance * distance - height * height, 0.0));
    const glm::dvec2 heading = horizontal > 0.0 ? glm::dvec2(offset.x, offset.z) / horizontal : glm::dvec2(0.0, 1.0);
    m_camera.position = m_camera.target + glm::dvec3(heading.x * across, height, heading.y * across);
}

void OrbitCamera::pan(QPointF pixels, QSize viewport)
{
    if (viewport.height() <= 0)
        return;
    const glm::dvec3 forward = glm::normalize(m_camera.target - m_camera.position);
    const glm::dvec3 worldUp(0.0, 1.0, 0.0);
    glm::dvec3 right = glm::cross(forward, worldUp);
    right = glm::length(right) > 1e-9 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 up = glm::cross(right, forward);
    // World units per pixel at the target's distance.
    const double distance = glm::length(m_camera.target - m_camera.position);
    const double perPixel = 2.0 * distance * std::tan(glm::radians(m_camera.fov) * 0.5) / viewport.height();
    const glm::dvec3 move = (-pixels.x() * right + pixels.y() * up) * perPixel;
    m_camera.position += move;
    m_camera.target += move;
    stayAboveGround();
}

void OrbitCamera::zoom(double steps)
{
    const glm::dvec3 offset = m_camera.position - m_camera.target;
    const double distance = glm::length(offset);
    const double wanted = std::clamp(distance * std::pow(kZoomPerStep, steps), kMinDistance, kMaxDistance);
    m_camera.position = m_camera.target + offset * (wanted / distance);
    stayAboveGround();
}

} // namespace shadowlab
