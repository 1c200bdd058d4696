#include "ConvexClipping.h"

#include "LightMath.h"

#include <glm/geometric.hpp>

#include <utility>

namespace shadowlab::convex {

std::vector<Polygon> hexahedronFaces(const std::array<glm::dvec3, 8>& c)
{
    std::vector<Polygon> faces;
    faces.reserve(kHexahedronFaces.size());
    for (const std::array<int, 4>& face : kHexahedronFaces)
        faces.push_back({c[std::size_t(face[0])], c[std::size_t(face[1])], c[std::size_t(face[2])], c[std::size_t(face[3])]});
    return faces;
}

std::array<Plane, 6> boxPlanes(const Bounds& b)
{
    // Planes written out, not derived from the faces: a flat box (a ground plane) has faces of
    // zero area but perfectly good planes.
    return {{{{1, 0, 0}, -b.min.x}, {{-1, 0, 0}, b.max.x}, {{0, 1, 0}, -b.min.y}, {{0, -1, 0}, b.max.y}, {{0, 0, 1}, -b.min.z}, {{0, 0, -1}, b.max.z}}};
}

Hull boxHull(const Bounds& b)
{
    const std::array<Plane, 6> planes = boxPlanes(b);
    return {hexahedronFaces(b.corners()), {planes.begin(), planes.end()}};
}

std::array<Plane, 6> frustumPlanes(const glm::dmat4& m)
{
    std::array<Plane, 6> planes;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const glm::dvec4 p = matrixRow(m, 3) + (side == 0 ? 1.0 : -1.0) * matrixRow(m, axis);
            const double length = glm::length(glm::dvec3(p));
            planes[std::size_t(2 * axis + side)] = length > 0.0 ? Plane{glm::dvec3(p) / length, p.w / length} : Plane{glm::dvec3(p), p.w};
        }
    }
    return planes;
}

Hull frustumHull(const glm::dmat4& m)
{
    const std::array<Plane, 6> planes = frustumPlanes(m);
    return {hexahedronFaces(frustumCorners(m)), {planes.begin(), planes.end()}};
}

void clipInto(const Polygon& polygon, const Plane& plane, Polygon& out)
{
    out.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = plane.distance(a);
        const double db = plane.distance(b);
        if (da >= 0.0)
            out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0))
            out.push_back(a + (b - a) * (da / (da - db)));
    }
}

Polygon clip(const Polygon& polygon, const Plane& plane)
{
    Polygon result;
    clipInto(polygon, plane, result);
    return result;
}

std::vector<Polygon> clipFaces(std::vector<Polygon> faces, const std::vector<Plane>& planes)
{
    std::vector<Polygon> result;
    for (Polygon& face : faces) {
        for (const Plane& plane : planes) {
            face = clip(face, plane);
            if (face.empty())
                break;
        }
        if (!face.empty())
            result.push_back(std::move(face));
    }
    return result;
}

Hull intersect(const Hull& a, const Hull& b)
{
    Hull result;
    result.faces = clipFaces(a.faces, b.planes);
    std::vector<Polygon> fromB = clipFaces(b.faces, a.planes);
    result.faces.insert(result.faces.end(), std::make_move_iterator(fromB.begin()), std::make_move_iterator(fromB.end()));
    result.planes = a.planes;
    result.planes.insert(result.planes.end(), b.planes.begin(), b.planes.end());
    return result;
}

double area(const std::vector<Polygon>& faces)
{
    double sum = 0.0;
    for (const Polygon& face : faces) {
        glm::dvec3 twice(0.0);
        for (std::size_t i = 0; i < face.size(); ++i)
            twice += glm::cross(face[i], face[(i + 1) % face.size()]);
        sum += 0.5 * glm::length(twice);
    }
    return sum;
}

} // namespace shadowlab::convex
