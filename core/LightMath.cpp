#include "LightMath.h"

#include "SettingsError.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

LightAngles lightAngles(const glm::dvec3& position, const glm::dvec3& target, double previousAzimuth)
{
    const glm::dvec3 offset = position - target;
    LightAngles angles;
    angles.distance = glm::length(offset);
    const double horizontal = std::hypot(offset.x, offset.z);
    angles.elevation = glm::degrees(std::atan2(offset.y, horizontal));
    // Within a millionth of the distance of the vertical, the azimuth says nothing.
    angles.azimuth = horizontal > 1e-6 * angles.distance ? glm::degrees(std::atan2(offset.x, offset.z)) : previousAzimuth;
    return angles;
}

glm::dvec3 lightPosition(const glm::dvec3& target, const LightAngles& angles)
{
    const double azimuth = glm::radians(angles.azimuth), elevation = glm::radians(std::clamp(angles.elevation, -90.0, 90.0));
    const glm::dvec3 direction(std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth));
    return target + direction * angles.distance;
}

glm::dmat4 stableLookAt(const glm::dvec3& eye, const glm::dvec3& target)
{
    return stableLookAlong(eye, target - eye);
}

glm::dmat4 stableLookAlong(const glm::dvec3& eye, const glm::dvec3& direction, const glm::dvec3& preferredUp)
{
    const glm::dvec3 forward = glm::normalize(direction);
    // World up unless the view is within ~2.5 degrees of vertical; then world -z, which is
    // as good as any other horizontal axis and keeps "up" on the map stable.
    const double across = glm::length(glm::cross(forward, preferredUp));
    const glm::dvec3 up = across > 1e-6 * glm::length(preferredUp) && across > 0.0 ? preferredUp
        : std::abs(forward.y) > 0.999                                             ? glm::dvec3(0.0, 0.0, -1.0)
                                                                                  : glm::dvec3(0.0, 1.0, 0.0);
    // glm::lookAt's basis, from the direction itself: eye + direction would round away
    // the direction's low bits when the eye is far from the origin.
    const glm::dvec3 side = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 upward = glm::cross(side, forward);
    glm::dmat4 view(1.0);
    for (int i = 0; i < 3; ++i) {
        view[i][0] = side[i];
        view[i][1] = upward[i];
        view[i][2] = -forward[i];
    }
    view[3][0] = -glm::dot(side, eye);
    view[3][1] = -glm::dot(upward, eye);
    view[3][2] = glm::dot(forward, eye);
    return view;
}

LightVolume manualVolume(const LightSettings& light)
{
    const double distance = glm::length(light.position - light.target);
    if (!(distance > 0.0) || !std::isfinite(distance))
        throw SettingsError(QStringLiteral("light.position"), QStringLiteral("the light must be away from its target"));
    if (!(light.nearPlane < light.farPlane))
        throw SettingsError(QStringLiteral("light.far"), QStringLiteral("far must be greater than near"));
    LightVolume v;
    v.origin = light.position;
    v.direction = (light.target - light.position) / distance;
    v.perspective = light.projection == LightProjection::Perspective;
    v.nearPlane = light.nearPlane;
    v.farPlane = light.farPlane;
    if (v.perspective) {
        if (!(light.nearPlane > 0.0))
            throw SettingsError(QStringLiteral("light.near"), QStringLiteral("a perspective light needs near > 0"));
        if (!(light.fov > 0.0 && light.fov < 180.0))
            throw SettingsError(QStringLiteral("light.fov"), QStringLiteral("the field of view must be in (0, 180) degrees"));
        const double t = std::tan(glm::radians(light.fov) * 0.5);
        v.left = v.bottom = -t;
        v.right = v.top = t;
    } else {
        if (!(light.extent > 0.0))
            throw SettingsError(QStringLiteral("light.extent"), QStringLiteral("the ortho half-size must be > 0"));
        v.left = v.bottom = -light.extent;
        v.right = v.top = light.extent;
    }
    return v;
}

LightFrame computeLightFrame(const LightSettings& light, bool reversedDepth)
{
    return computeLightFrame(light, manualVolume(light), reversedDepth);
}

LightFrame computeLightFrame(const LightSettings& light, const LightVolume& v, bool reversedDepth)
{
    const double distance = glm::length(light.position - light.target);
    if (!(distance > 0.0) || !std::isfinite(distance))
        throw SettingsError(QStringLiteral("light.position"), QStringLiteral("the light must be away from its target"));
    if (!(v.nearPlane < v.farPlane) || !(v.left < v.right) || !(v.bottom < v.top) || (v.perspective && !(v.nearPlane > 0.0)))
        throw SettingsError(QStringLiteral("light"), QStringLiteral("the light's volume is empty; check light.near, light.far, light.extent and light.fov"));

    LightFrame f;
    f.volume = v;
    f.position = light.position;
    f.direction = (light.target - light.position) / distance;
    f.targetDistance = distance;
    f.perspective = v.perspective;
    f.nearPlane = v.nearPlane;
    f.farPlane = v.farPlane;
    if (light.type == LightType::Spot)
        f.spotCosine = std::cos(glm::radians(light.fov) * 0.5);
    f.view = stableLookAlong(v.origin, v.direction, v.up);
    if (f.perspective) {
        const double n = v.nearPlane;
        f.projection = glm::frustum(v.left * n, v.right * n, v.bottom * n, v.top * n, n, v.farPlane);
    } else if (v.warped) {
        f.projection = v.warp;
    } else {
        f.projection = glm::ortho(v.left, v.right, v.bottom, v.top, v.nearPlane, v.farPlane);
    }
    f.viewProjection = f.projection * f.view;
    // Clip space [-1, 1] to texture space [0, 1].
    const glm::dmat4 toTexture = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    f.shadowMatrix = toTexture * f.viewProjection;
    // Reversed depth: z' = w - z maps conventional window depth d to 1 - d after the divide;
    // with clip control zero-to-one the rasteriser stores it without the 0.5 z + 0.5 step, so
    // float depth keeps its fine steps near 0, which is now the far end where they are needed.
    f.reversedDepth = reversedDepth;
    f.depthViewProjection = f.viewProjection;
    f.depthShadowMatrix = f.shadowMatrix;
    if (reversedDepth) {
        glm::dmat4 zeroToOne(1.0);   // clip z in [-w, w] -> [0, w]
        zeroToOne[2][2] = 0.5;
        zeroToOne[3][2] = 0.5;
        glm::dmat4 flip(1.0);        // z -> w - z
        flip[2][2] = -1.0;
        flip[3][2] = 1.0;
        f.depthViewProjection = flip * zeroToOne * f.viewProjection;
        f.depthShadowMatrix = flip * f.shadowMatrix;
    }
    if (!isFinite(f.shadowMatrix) || !isFinite(f.depthShadowMatrix))
        throw SettingsError(QStringLiteral("light"), QStringLiteral("the light's matrices are not finite; bring near, far and the positions into a sane range"));
    return f;
}

CameraFrame computeCameraFrame(const CameraSettings& camera, double aspect, const Bounds& sceneBounds)
{
    CameraFrame f;
    f.position = camera.position;
    f.view = stableLookAt(camera.position, camera.target);
    double farthest = 1.0;
    double nearest = 0.0;
    if (!sceneBounds.isEmpty()) {
        for (const glm::dvec3& c : sceneBounds.corners())
            farthest = std::max(farthest, glm::length(c - camera.position));
        const glm::dvec3 closest = glm::clamp(camera.position, sceneBounds.min, sceneBounds.max);
        nearest = glm::length(closest - camera.position);
    }
    f.farPlane = farthest * 1.05;
    f.nearPlane = std::max({nearest * 0.5, f.farPlane * 1e-4, 1e-3});
    aspect = std::isfinite(aspect) && aspect > 0.0 ? aspect : 1.0;
    f.projection = glm::perspective(glm::radians(camera.fov), aspect, f.nearPlane, f.farPlane);
    f.viewProjection = f.projection * f.view;
    return f;
}

double texelWorldSize(const LightVolume& volume, int mapSize, double distance)
{
    if (mapSize <= 0)
        return 0.0;
    if (volume.warped && !volume.perspective) {
        double coarsest = 0.0;
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 corner((i & 1) ? volume.right : volume.left, (i & 2) ? volume.top : volume.bottom,
                                    -((i & 4) ? volume.farPlane : volume.nearPlane));
            coarsest = std::max(coarsest, warpedTexelSize(volume, mapSize, corner));
        }
        return coarsest;
    }
    const double span = std::max(volume.width(), volume.height()) / mapSize;
    return volume.perspective ? span * distance : span;
}

double warpedTexelSize(const LightVolume& volume, int mapSize, const glm::dvec3& p)
{
    // The map's uv changes across the light's rays (view x and y) at p; a texel is the world
    // step that moves uv by 1 / mapSize along one axis of the map.
    const glm::dvec4 c = volume.warp * glm::dvec4(p, 1.0);
    if (!(c.w > 0.0) || mapSize <= 0)
        return 0.0;
    const glm::dvec2 uv = glm::dvec2(c) / c.w;
    const glm::dvec4 cx = volume.warp * glm::dvec4(1.0, 0.0, 0.0, 0.0);
    const glm::dvec4 cy = volume.warp * glm::dvec4(0.0, 1.0, 0.0, 0.0);
    const glm::dvec2 jx = (glm::dvec2(cx) - uv * cx.w) / c.w;   // clip [-1, 1] per world unit along x
    const glm::dvec2 jy = (glm::dvec2(cy) - uv * cy.w) / c.w;
    const double det = jx.x * jy.y - jy.x * jx.y;
    if (!(std::abs(det) > 0.0))
        return 0.0;
    // Columns of the inverse: world (x, y) per clip unit of the map's x and of its y.
    const double perX = glm::length(glm::dvec2(jy.y, -jx.y)) / std::abs(det);
    const double perY = glm::length(glm::dvec2(-jy.x, jx.x)) / std::abs(det);
    return std::max(perX, perY) * 2.0 / double(mapSize);
}

double texelWorldSize(const LightSettings& light, int mapSize)
{
    return texelWorldSize(manualVolume(light), mapSize, glm::length(light.position - light.target));
}

bool isOutsideFrustum(const glm::dmat4& viewProjection, const Bounds& box, bool ignoreNear)
{
    if (box.isEmpty())
        return true;
    // Count corners outside each clip plane: -w <= x, y, z <= w.
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (const glm::dvec3& c : box.corners()) {
        const glm::dvec4 p = viewProjection * glm::dvec4(c, 1.0);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
        outside[5] += p.z > p.w;
    }
    for (int plane = 0; plane < 6; ++plane) {
        if (plane == 4 && ignoreNear)
            continue;
        if (outside[plane] == 8)
            return true;
    }
    return false;
}

std::array<glm::dvec3, 8> frustumCorners(const glm::dmat4& viewProjection)
{
    const glm::dmat4 inverse = glm::inverse(viewProjection);
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p = inverse * glm::dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        corners[std::size_t(i)] = glm::dvec3(p) / p.w;
    }
    return corners;
}

bool isFinite(const glm::dmat4& m)
{
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r]))
                return false;
        }
    }
    return true;
}

} // namespace shadowlab
