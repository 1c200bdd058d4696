#include "LightWarp.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowlab {

namespace {

double smoothStep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// What the warp must cover, in the box's light view space (x, y across the map, z = -depth):
// the outline at the box's near and far depth, or the box's corners.
std::vector<glm::dvec3> focusPoints(const LightVolume& v, const std::vector<glm::dvec2>& outline)
{
    std::vector<glm::dvec3> points;
    if (outline.size() >= 3) {
        for (const glm::dvec2& p : outline) {
            points.emplace_back(p, -v.nearPlane);
            points.emplace_back(p, -v.farPlane);
        }
        return points;
    }
    for (int i = 0; i < 8; ++i)
        points.emplace_back((i & 1) ? v.right : v.left, (i & 2) ? v.top : v.bottom, -((i & 4) ? v.farPlane : v.nearPlane));
    return points;
}

} // namespace

glm::dvec3 warpAxis(const CameraFrame& camera, const glm::dvec3& direction)
{
    const glm::dvec3 forward = -glm::dvec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]);
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec3 across = forward - d * glm::dot(forward, d);
    const double length = glm::length(across);
    return length > kWarpFadeStart && std::isfinite(length) ? across / length : glm::dvec3(0.0);
}

namespace {

// Wimmer's optimum n = (z_n + sqrt(z_n z_f)) / sin(gamma), times the user's scale, and
// growing without bound as the fade goes to 0. The depths are the focus's own where they are
// narrower than the receivers' (casters over part of a wide ground): the warp is fitted to what
// the map covers.
double warpNearDistance(const std::vector<glm::dvec3>& corners, const glm::dmat4& lightView, const CameraFrame& camera,
                        const WarpFocus& focus, double sinGamma, double fade)
{
    const glm::dmat4 toCamera = camera.view * glm::inverse(lightView);
    double focusNear = 1e300, focusFar = 0.0;
    for (const glm::dvec3& c : corners) {
        const double depth = -(toCamera * glm::dvec4(c, 1.0)).z;
        focusNear = std::min(focusNear, depth);
        focusFar = std::max(focusFar, depth);
    }
    const double zNear = std::max({focus.nearDepth, focusNear, 1e-9});
    const double zFar = std::max(std::min(focus.farDepth, focusFar), zNear);
    const double optimum = (zNear + std::sqrt(zNear * zFar)) / sinGamma;
    return optimum * focus.scale / fade;
}

// The perspective along the turned map's y: the centre of projection n before the focus's near
// side (`low`) and across from the eye; clip (n x, A y + B, n z, y), y in [n, n + d] to [-1, 1].
glm::dmat4 warpPerspective(double n, double d, double low, double eyeX)
{
    glm::dmat4 shift(1.0);
    shift[3] = glm::dvec4(-eyeX, -(low - n), 0.0, 1.0);
    const double far = n + d;
    glm::dmat4 perspective(0.0);
    perspective[0][0] = n;
    perspective[1][1] = (far + n) / d;
    perspective[1][3] = 1.0;
    perspective[2][2] = n;
    perspective[3][1] = -2.0 * n * far / d;
    return perspective * shift;
}

// x and depth fitted to the warped focus: the image of a convex prism is the hull of its corners'.
glm::dmat4 fitWarpedFocus(const glm::dmat4& warp, const std::vector<glm::dvec3>& corners)
{
    glm::dvec2 xRange(1e300, -1e300), zRange(1e300, -1e300);
    for (const glm::dvec3& c : corners) {
        const glm::dvec4 q = warp * glm::dvec4(c, 1.0);
        xRange = glm::dvec2(std::min(xRange.x, q.x / q.w), std::max(xRange.y, q.x / q.w));
        zRange = glm::dvec2(std::min(zRange.x, q.z / q.w), std::max(zRange.y, q.z / q.w));
    }
    const double xSpan = std::max(xRange.y - xRange.x, 1e-12), zSpan = std::max(zRange.y - zRange.x, 1e-12);
    glm::dmat4 fit(1.0);
    fit[0][0] = 2.0 / xSpan;
    fit[3][0] = -(xRange.x + xRange.y) / xSpan;
    // Nearest the light (largest view z) to -1, as glm::ortho's depth.
    fit[2][2] = -2.0 / zSpan;
    fit[3][2] = (zRange.x + zRange.y) / zSpan;
    return fit * warp;
}

} // namespace

LightVolume lispsmVolume(const LightVolume& box, const CameraFrame& camera, const WarpFocus& focus, WarpShape* shape)
{
    WarpShape unused;
    WarpShape& out = shape ? *shape : unused;
    out = WarpShape{};
    LightVolume result = box;
    result.warped = false;
    result.warp = glm::dmat4(1.0);
    if (box.perspective)
        return result;

    // The camera's view direction as the map sees it: its part across the light's rays.
    const glm::dmat4 view = stableLookAlong(box.origin, box.direction, box.up);
    const glm::dvec3 forward = -glm::dvec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]);
    const glm::dvec3 f(view * glm::dvec4(forward, 0.0));
    const double across = glm::length(glm::dvec2(f)), along = std::abs(f.z);
    out.sinGamma = across / std::max(std::hypot(across, along), 1e-300);
    const double fade = smoothStep(kWarpFadeStart, kWarpFadeEnd, out.sinGamma);
    if (!(fade > 0.0) || !std::isfinite(out.sinGamma))
        return result;
    const glm::dvec2 axis = glm::dvec2(f) / across;

    // R turns the map so its y runs along that direction: y' = axis . (x, y).
    glm::dmat4 turn(1.0);
    turn[0] = glm::dvec4(axis.y, axis.x, 0.0, 0.0);
    turn[1] = glm::dvec4(-axis.x, axis.y, 0.0, 0.0);
    const std::vector<glm::dvec3> corners = focusPoints(box, focus.outline);
    double low = 1e300, high = -1e300;
    for (const glm::dvec3& c : corners) {
        const double y = glm::dot(axis, glm::dvec2(c));
        low = std::min(low, y);
        high = std::max(high, y);
    }
    const double extent = std::max({box.width(), box.height(), box.farPlane - box.nearPlane});
    const double d = std::max(high - low, extent * 1e-9);
    const double n = std::max(warpNearDistance(corners, view, camera, focus, out.sinGamma, fade), d * 1e-6);
    if (!std::isfinite(n) || n > kWarpLongest * d)
        return result;

    const glm::dvec3 eye(turn * view * glm::dvec4(camera.position, 1.0));
    const glm::dmat4 projection = fitWarpedFocus(warpPerspective(n, d, low, eye.x) * turn, corners);
    if (!isFinite(projection))
        return result;
    result.warped = true;
    result.warp = projection;
    out.warped = true;
    out.nearDistance = n;
    out.depth = d;
    return result;
}

double warpNearGain(const LightVolume& warped, const LightVolume& plain, int mapSize, const CameraFrame& camera,
                    const std::vector<glm::dvec2>& outline)
{
    if (!warped.warped || plain.warped || plain.perspective || mapSize <= 0)
        return 1.0;
    const glm::dmat4 view = stableLookAlong(warped.origin, warped.direction, warped.up);
    const glm::dmat4 toCamera = camera.view * glm::inverse(view);
    // The warp keeps a ray's texel along it, so the outline at the box's middle depth will do.
    const double middle = -0.5 * (warped.nearPlane + warped.farPlane);
    std::vector<glm::dvec2> points = outline;
    if (points.size() < 3)
        points = {{warped.left, warped.bottom}, {warped.right, warped.bottom}, {warped.left, warped.top}, {warped.right, warped.top}};
    std::optional<glm::dvec3> nearest;
    double nearestDepth = 1e300;
    for (const glm::dvec2& p : points) {
        const double depth = -(toCamera * glm::dvec4(p, middle, 1.0)).z;
        if (depth >= camera.nearPlane && depth < nearestDepth) {
            nearestDepth = depth;
            nearest = glm::dvec3(p, middle);
        }
    }
    if (!nearest)
        return 1.0;
    // The warped texel there: the map's clip per world unit across the rays, inverted.
    const glm::dvec4 c = warped.warp * glm::dvec4(*nearest, 1.0);
    if (!(c.w > 0.0))
        return 1.0;
    const glm::dvec2 uv = glm::dvec2(c) / c.w;
    const glm::dvec4 cx = warped.warp * glm::dvec4(1.0, 0.0, 0.0, 0.0);
    const glm::dvec4 cy = warped.warp * glm::dvec4(0.0, 1.0, 0.0, 0.0);
    const glm::dvec2 jx = (glm::dvec2(cx) - uv * cx.w) / c.w;
    const glm::dvec2 jy = (glm::dvec2(cy) - uv * cy.w) / c.w;
    const double det = std::abs(jx.x * jy.y - jy.x * jx.y);
    if (!(det > 0.0) || !std::isfinite(det))
        return 1.0;
    const double warpedTexel = 2.0 / (double(mapSize) * std::sqrt(det));
    const double plainTexel = std::sqrt(plain.width() * plain.height()) / double(mapSize);
    const double gain = plainTexel / warpedTexel;
    return std::isfinite(gain) && gain > 0.0 ? gain : 1.0;
}

} // namespace shadowlab
