#pragma once

#include <optional>

#include "Settings.h"

#include <QPointF>
#include <QSize>

namespace shadowlab {

// Orbit, pan and zoom of a camera around its target, as pure math on CameraSettings (no GL,
// no widgets): the scene view turns mouse motion into these calls and hands the result on.
// Pitch stays short of the poles so the camera never looks straight along its up axis.
class OrbitCamera {
public:
    // With a ground height, orbits, pans and zooms keep the camera above that plane.
    explicit OrbitCamera(const CameraSettings& camera, std::optional<double> ground = std::nullopt) : m_camera(camera), m_ground(ground) {}

    const CameraSettings& settings() const { return m_camera; }

    // Turns around the target: yaw about world up, pitch toward or away from it, in degrees.
    void orbit(double yawDegrees, double pitchDegrees);
    // Moves camera and target together so the point under the cursor follows a drag of
    // `pixels` in a viewport of `viewport` pixels (at the target's depth).
    void pan(QPointF pixels, QSize viewport);
    // Moves toward the target (steps > 0) or away, by a fixed ratio per step; never onto it.
    void zoom(double steps);

private:
    void stayAboveGround();

    CameraSettings m_camera;
    std::optional<double> m_ground;
};

} // namespace shadowlab
