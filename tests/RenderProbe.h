#pragma once

#include "LightMath.h"

#include <glm/glm.hpp>

#include <QImage>
#include <QPoint>

#include <optional>

// Helpers for GL tests that look at rendered images the way a person would: where does this
// world point land on screen, and how bright is it there.
namespace probe {

// Pixel of a world point for `camera` on an image of `size` (y down); nullopt when behind the
// camera or off screen.
inline std::optional<QPoint> project(const shadowlab::CameraFrame& camera, const glm::dvec3& world, QSize size)
{
    const glm::dvec4 clip = camera.viewProjection * glm::dvec4(world, 1.0);
    if (clip.w <= 0.0)
        return std::nullopt;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    const int x = int((ndc.x * 0.5 + 0.5) * size.width());
    const int y = int((0.5 - ndc.y * 0.5) * size.height());
    if (x < 0 || y < 0 || x >= size.width() || y >= size.height())
        return std::nullopt;
    return QPoint(x, y);
}

inline double luminance(const QImage& image, QPoint p)
{
    const QRgb c = image.pixel(p);
    return 0.2126 * qRed(c) + 0.7152 * qGreen(c) + 0.0722 * qBlue(c);
}

// Brightness with shadows relative to the same pixel without: ~1 lit, ~0.3 (ambient) in shadow.
inline double visibilityRatio(const QImage& withShadows, const QImage& withoutShadows, QPoint p)
{
    return luminance(withShadows, p) / std::max(1.0, luminance(withoutShadows, p));
}

// Does the segment from `point` toward the light hit the unit cube [-1, 1]^3 placed by `model`?
// (Slab test in the cube's object space: the ground truth for cube casters.)
inline bool rayHitsCube(const glm::dmat4& model, const glm::dvec3& point, const glm::dvec3& towardLight)
{
    const glm::dmat4 inverse = glm::inverse(model);
    const glm::dvec3 o = glm::dvec3(inverse * glm::dvec4(point, 1.0));
    const glm::dvec3 d = glm::dvec3(inverse * glm::dvec4(towardLight, 0.0));
    double tNear = 1e-6, tFar = 1e30;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(d[axis]) < 1e-15) {
            if (o[axis] < -1.0 || o[axis] > 1.0)
                return false;
            continue;
        }
        double t0 = (-1.0 - o[axis]) / d[axis];
        double t1 = (1.0 - o[axis]) / d[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar)
            return false;
    }
    return true;
}

} // namespace probe
