#include "LightFitting.h"

#include "LightMath.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

using Polygon = std::vector<glm::dvec3>;

// Inside where dot(n, p) + d >= 0.
struct Plane {
    glm::dvec3 n;
    double d;
    double distance(const glm::dvec3& p) const { return glm::dot(n, p) + d; }
};

// A convex region as its faces and its bounding planes: intersecting two of them clips each
// one's faces by the other's planes, so every vertex of the intersection is found.
struct Hull {
    std::vector<Polygon> faces;
    std::vector<Plane> planes;
};

// Corner i has x from bit 0, y from bit 1, z from bit 2 (as Bounds::corners() and frustumCorners()).
std::vector<Polygon> hexahedronFaces(const std::array<glm::dvec3, 8>& c)
{
    return {{c[0], c[2], c[6], c[4]}, {c[1], c[5], c[7], c[3]}, {c[0], c[4], c[5], c[1]},
            {c[2], c[3], c[7], c[6]}, {c[0], c[1], c[3], c[2]}, {c[4], c[6], c[7], c[5]}};
}

Hull boxHull(const Bounds& b)
{
    // Planes written out, not derived from the faces: a flat box (a ground plane) has faces of
    // zero area but perfectly good planes.
    return {hexahedronFaces(b.corners()),
            {{{1, 0, 0}, -b.min.x}, {{-1, 0, 0}, b.max.x}, {{0, 1, 0}, -b.min.y}, {{0, -1, 0}, b.max.y},
             {{0, 0, 1}, -b.min.z}, {{0, 0, -1}, b.max.z}}};
}

Hull frustumHull(const glm::dmat4& m)
{
    Hull h{hexahedronFaces(frustumCorners(m)), {}};
    const auto row = [&m](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {1.0, -1.0}) {
            const glm::dvec4 p = row(3) + sign * row(axis);   // Gribb-Hartmann: -w <= x, y, z <= w
            const double length = glm::length(glm::dvec3(p));
            if (length > 0.0)
                h.planes.push_back({glm::dvec3(p) / length, p.w / length});
        }
    }
    return h;
}

Polygon clip(const Polygon& polygon, const Plane& plane)
{
    Polygon result;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = plane.distance(a);
        const double db = plane.distance(b);
        if (da >= 0.0)
            result.push_back(a);
        if ((da >= 0.0) != (db >= 0.0))
            result.push_back(a + (b - a) * (da / (da - db)));
    }
    return result;
}

Hull intersect(const Hull& a, const Hull& b)
{
    Hull result;
    const auto clipAll = [&result](const Hull& from, const Hull& by) {
        for (Polygon face : from.faces) {
            for (const Plane& plane : by.planes) {
                face = clip(face, plane);
                if (face.empty())
                    break;
            }
            if (!face.empty())
                result.faces.push_back(std::move(face));
        }
    };
    clipAll(a, b);
    clipAll(b, a);
    result.planes = a.planes;
    result.planes.insert(result.planes.end(), b.planes.begin(), b.planes.end());
    return result;
}

// Steps of 2^(1/4): coarse enough that a moving camera rarely crosses one, fine enough to
// waste at most 19 % of the texels.
constexpr double kStepsPerOctave = 4.0;

double ladderUp(double x) { return std::exp2(std::ceil(std::log2(x) * kStepsPerOctave) / kStepsPerOctave); }
double ladderDown(double x) { return std::exp2(std::floor(std::log2(x) * kStepsPerOctave) / kStepsPerOctave); }

} // namespace

std::vector<glm::dvec3> clipBoxToFrusta(const Bounds& box, const std::vector<glm::dmat4>& viewProjections)
{
    if (box.isEmpty())
        return {};
    Hull hull = boxHull(box);
    for (const glm::dmat4& m : viewProjections)
        hull = intersect(hull, frustumHull(m));
    std::vector<glm::dvec3> points;
    for (const Polygon& face : hull.faces)
        points.insert(points.end(), face.begin(), face.end());
    return points;
}

FittedLight fitLight(const LightSettings& light, const std::vector<Bounds>& casters, const std::vector<Bounds>& receivers,
                  const std::optional<glm::dmat4>& camera, int mapSize)
{
    FittedLight result;
    result.light = light;
    result.texelBefore = result.texelAfter = texelWorldSize(light, mapSize);
    result.anythingToShadow = std::any_of(casters.begin(), casters.end(), [](const Bounds& b) { return !b.isEmpty(); });
    if (!result.anythingToShadow || light.fit == LightFit::Manual)
        return result;

    const LightFrame frame = computeLightFrame(light);
    const bool perspective = frame.perspective;
    // Light space: x and y across the map (tangents of the angle for a perspective light), and
    // distance from the light along its axis.
    const auto toLight = [&](const glm::dvec3& p) {
        const glm::dvec3 v(frame.view * glm::dvec4(p, 1.0));
        const double depth = -v.z;
        return perspective ? glm::dvec3(v.x / depth, v.y / depth, depth) : glm::dvec3(v.x, v.y, depth);
    };

    std::vector<glm::dmat4> seen{frame.viewProjection};
    if (camera)
        seen.push_back(*camera);
    Bounds region;
    for (const Bounds& receiver : receivers) {
        for (const glm::dvec3& p : clipBoxToFrusta(receiver, seen))
            region.extend(toLight(p));
    }
    if (region.isEmpty()) {
        result.anythingToShadow = false;
        return result;
    }

    // The casters that can shadow the region: their part inside the prism (ortho) or pyramid
    // (perspective) over the region that ends at the region's far side. An ortho prism starts
    // behind every caster: depth clamp lets casters before the near plane cast.
    double casterStart = light.nearPlane;
    if (!perspective) {
        for (const Bounds& caster : casters) {
            if (caster.isEmpty())
                continue;
            for (const glm::dvec3& c : caster.corners())
                casterStart = std::min(casterStart, toLight(c).z - 1.0);
        }
    }
    const glm::dmat4 prism = perspective
        ? glm::frustum(region.min.x * casterStart, region.max.x * casterStart, region.min.y * casterStart, region.max.y * casterStart,
                       casterStart, region.max.z)
        : glm::ortho(region.min.x, region.max.x, region.min.y, region.max.y, casterStart, region.max.z);
    double nearest = region.min.z;
    bool anyCaster = false;
    // A region of zero width (a receiver seen edge-on) gives no prism; then every caster counts.
    const bool prismValid = isFinite(prism) && region.max.x > region.min.x && region.max.y > region.min.y;
    for (const Bounds& caster : casters) {
        const std::vector<glm::dvec3> part = clipBoxToFrusta(caster, {prismValid ? prism * frame.view : frame.viewProjection});
        for (const glm::dvec3& p : part) {
            nearest = std::min(nearest, toLight(p).z);
            anyCaster = true;
        }
    }
    if (!anyCaster) {
        result.anythingToShadow = false;
        return result;
    }

    LightSettings fitted = light;
    const double texels = double(mapSize);
    if (perspective) {
        const double manualTan = std::tan(glm::radians(light.fov) * 0.5);
        double tanHalf = std::max({std::abs(region.min.x), std::abs(region.max.x), std::abs(region.min.y), std::abs(region.max.y)});
        tanHalf = std::max(tanHalf * (1.0 + 2.0 / texels), manualTan * 1e-6);   // one texel of margin
        double nearPlane = std::max(light.nearPlane, nearest * (1.0 - 1e-3));
        double farPlane = std::min(light.farPlane, region.max.z * (1.0 + 1e-3));
        if (light.stabilize) {
            tanHalf = ladderUp(tanHalf);
            nearPlane = std::max(light.nearPlane, ladderDown(nearPlane));
            farPlane = std::min(light.farPlane, ladderUp(farPlane));
        }
        fitted.fov = glm::degrees(2.0 * std::atan(std::min(tanHalf, manualTan)));
        fitted.nearPlane = nearPlane;
        fitted.farPlane = farPlane;
    } else {
        glm::dvec2 centre = (glm::dvec2(region.min) + glm::dvec2(region.max)) * 0.5;
        const glm::dvec2 size = glm::dvec2(region.max) - glm::dvec2(region.min);
        double half = std::max({size.x, size.y, light.extent * 1e-6}) * 0.5;
        double grid = 0.0;  // world units the centre and the depth range snap to
        if (light.stabilize) {
            // Snapping moves the centre by up to grid / 2 <= extent / 16: grow by 16/15 first.
            half = ladderUp(half * 16.0 / 15.0);
            grid = 2.0 * half / texels * std::max(1.0, std::floor(texels / 16.0));
            centre = glm::round(centre / grid) * grid;
        } else {
            half *= 1.0 + 2.0 / texels;
        }
        if (half >= light.extent) {
            half = light.extent;
            centre = glm::dvec2(0.0);
        } else if (grid == 0.0) {
            // Stay inside the volume as set (the region is inside it, so this keeps it covered).
            // A snapped centre may stick out by up to grid / 2 instead: clamping would undo the
            // whole-texel steps, and what it shows there is shadowed in truth too.
            centre = glm::clamp(centre, glm::dvec2(-(light.extent - half)), glm::dvec2(light.extent - half));
        }
        const double margin = grid > 0.0 ? grid : (region.max.z - nearest) * 1e-3 + 1e-9 * std::abs(region.max.z);
        double nearPlane = nearest - margin;
        double farPlane = region.max.z + margin;
        if (grid > 0.0) {
            nearPlane = std::floor(nearPlane / grid) * grid;
            farPlane = std::ceil(farPlane / grid) * grid;
        }
        fitted.extent = half;
        fitted.nearPlane = std::max(light.nearPlane, nearPlane);
        fitted.farPlane = std::min(light.farPlane, farPlane);
        // Move sideways along the map's axes; the direction, and with it the basis, stays.
        const glm::dvec3 shift = centre.x * glm::dvec3(frame.view[0][0], frame.view[1][0], frame.view[2][0])
                               + centre.y * glm::dvec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
        fitted.position += shift;
        fitted.target += shift;
    }
    if (!(fitted.nearPlane < fitted.farPlane)) {
        // Everything at one depth (a single flat receiver facing the light): keep the set range.
        fitted.nearPlane = light.nearPlane;
        fitted.farPlane = light.farPlane;
    }
    result.light = fitted;
    result.fitted = !(fitted == light);
    result.texelAfter = texelWorldSize(fitted, mapSize);
    return result;
}

} // namespace shadowlab
