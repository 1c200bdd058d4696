#include "LightMath.h"

#include "SettingsError.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

glm::dmat4 stableLookAt(const glm::dvec3& eye, const glm::dvec3& target)
{
    const glm::dvec3 forward = glm::normalize(target - eye);
    // World up unless the view is within ~2.5 degrees of vertical; then world -z, which is
    // as good as any other horizontal axis and keeps "up" on the map stable.
    const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::lookAt(eye, target, up);
}

LightFrame computeLightFrame(const LightSettings& light, bool reversedDepth)
{
    const double distance = glm::length(light.position - light.target);
    if (!(distance > 0.0) || !std::isfinite(distance))
        throw SettingsError(QStringLiteral("light.position"), QStringLiteral("the light must be away from its target"));
    if (!(light.nearPlane < light.farPlane))
        throw SettingsError(QStringLiteral("light.far"), QStringLiteral("far must be greater than near"));

    LightFrame f;
    f.position = light.position;
    f.direction = (light.target - light.position) / distance;
    f.targetDistance = distance;
    f.perspective = light.projection == LightProjection::Perspective;
    f.nearPlane = light.nearPlane;
    f.farPlane = light.farPlane;
    f.view = stableLookAt(light.position, light.target);
    if (f.perspective) {
        if (!(light.nearPlane > 0.0))
            throw SettingsError(QStringLiteral("light.near"), QStringLiteral("a perspective light needs near > 0"));
        if (!(light.fov > 0.0 && light.fov < 180.0))
            throw SettingsError(QStringLiteral("light.fov"), QStringLiteral("the field of view must be in (0, 180) degrees"));
        f.projection = glm::perspective(glm::radians(light.fov), 1.0, light.nearPlane, light.farPlane);
    } else {
        if (!(light.extent > 0.0))
            throw SettingsError(QStringLiteral("light.extent"), QStringLiteral("the ortho half-size must be > 0"));
        f.projection = glm::ortho(-light.extent, light.extent, -light.extent, light.extent, light.nearPlane, light.farPlane);
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

double texelWorldSize(const LightSettings& light, int mapSize)
{
    if (mapSize <= 0)
        return 0.0;
    if (light.projection == LightProjection::Ortho)
        return 2.0 * light.extent / mapSize;
    const double distance = glm::length(light.position - light.target);
    return 2.0 * distance * std::tan(glm::radians(light.fov) * 0.5) / mapSize;
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
