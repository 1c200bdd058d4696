#pragma once

// Convex regions in double precision, clipped against each other: a light's volume, the camera's
// frustum and the scene's box, for the fit (LightFitting.cpp). Pure maths, no GL.

#include "Bounds.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <vector>

namespace shadowlab::convex {

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

// The six faces of a box or frustum; corner i has x from bit 0, y from bit 1, z from bit 2 (as
// Bounds::corners() and frustumCorners()). kHexahedronFaces: each face's corners by index.
constexpr std::array<std::array<int, 4>, 6> kHexahedronFaces{{{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}}};
std::vector<Polygon> hexahedronFaces(const std::array<glm::dvec3, 8>& c);
Hull boxHull(const Bounds& b);
// boxHull's planes: the box's six faces', inside where it is.
std::array<Plane, 6> boxPlanes(const Bounds& b);
// Row i of a matrix, as the affine function that gives coordinate i of its product.
inline glm::dvec4 matrixRow(const glm::dmat4& m, int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); }
// The six planes -w <= x, y, z <= w of a view-projection (Gribb-Hartmann), in the order left,
// right, bottom, top, near, far; always six, so an index names a plane.
std::array<Plane, 6> frustumPlanes(const glm::dmat4& m);
Hull frustumHull(const glm::dmat4& m);

// The part of `polygon` inside `plane` (Sutherland-Hodgman); clipInto writes it to `out`, whose
// memory a caller clipping many polygons keeps.
Polygon clip(const Polygon& polygon, const Plane& plane);
void clipInto(const Polygon& polygon, const Plane& plane, Polygon& out);
// The part of each face inside every plane; faces clipped away are dropped.
std::vector<Polygon> clipFaces(std::vector<Polygon> faces, const std::vector<Plane>& planes);
Hull intersect(const Hull& a, const Hull& b);
// The faces' total area.
double area(const std::vector<Polygon>& faces);

} // namespace shadowlab::convex
