#pragma once

// Boxes clipped to frusta, as the light's fit clips a scene's objects to the camera's view and
// to its own volume (LightFitting.cpp). Pure maths in double, no GL.

#include "Bounds.h"
#include "ConvexClipping.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <utility>
#include <vector>

namespace shadowlab {

// A box as its centre and half size, for the least and greatest of an affine function over it
// (dot(f.xyz, p) + f.w: a row of a matrix): at the centre, less and plus the spread, one dot
// product each instead of eight corners through the matrix.
struct BoxExtent {
    glm::dvec3 centre;
    glm::dvec3 half;
    explicit BoxExtent(const Bounds& box) : centre((box.min + box.max) * 0.5), half((box.max - box.min) * 0.5) {}
    double least(const glm::dvec4& f) const { return middle(f) - spread(f); }
    double greatest(const glm::dvec4& f) const { return middle(f) + spread(f); }
    double middle(const glm::dvec4& f) const { return glm::dot(glm::dvec3(f), centre) + f.w; }
    double spread(const glm::dvec4& f) const { return glm::dot(glm::abs(glm::dvec3(f)), half); }
};
// The least and greatest over `box` of coordinate i of m * (p, 1), each taken at the corner the
// row's signs pick and summed in the order glm's product sums: rounding is monotone, so they are
// exactly the least and greatest of the eight corners' own products, for two of them.
std::pair<double, double> coordinateRange(const glm::dmat4& m, int i, const Bounds& box);

// Where `box` lies against the frustum of `viewProjection`: wholly outside one of its planes
// (as isOutsideFrustum, the near plane included); inside with room to spare, so that clipping
// the box to it keeps every face as it is and leaves none of the frustum's; or across it.
enum class FrustumSide { Outside, WellInside, Across };
FrustumSide frustumSide(const Bounds& box, const glm::dmat4& viewProjection);

// The vertices of the convex region `box` ∩ each frustum (conventional clip space of each
// view-projection): empty when they do not overlap or the box lies wholly outside one of them
// (isOutsideFrustum); a box well inside every frustum is its eight corners. Exposed for tests of
// the fit.
std::vector<glm::dvec3> clipBoxToFrusta(const Bounds& box, const std::vector<glm::dmat4>& viewProjections);

// clipBoxToFrusta for many boxes against the same frusta, as the fit clips every object of a
// scene each time the camera moves: each frustum's faces and planes are found once, on the
// first box that crosses it, and faces are clipped in buffers kept from box to box, so after the
// first few boxes a clip allocates nothing. A box that crosses a frustum gives the same points
// as intersecting the hulls (convex::intersect), in the same order; one well inside every
// frustum its eight corners.
class FrustaClip {
public:
    explicit FrustaClip(const std::vector<glm::dmat4>& viewProjections);
    // The vertices of `box` ∩ every frustum, valid until the next call.
    const std::vector<glm::dvec3>& operator()(const Bounds& box);
    // Whether the last box lay well inside every frustum, so that its part is the whole box.
    bool whole() const { return m_whole; }

private:
    struct Frustum {
        glm::dmat4 viewProjection;
        std::vector<convex::Polygon> faces;     // empty until a box crosses it
        std::array<convex::Plane, 6> planes;
    };
    // Appends the face in m_face clipped by the planes of every source but `own` (0 the box, k
    // the k-th of `cutting`), in their order, as intersecting their hulls one by one does.
    void appendClipped(std::size_t own, const std::array<convex::Plane, 6>& boxSides);

    std::vector<Frustum> m_frusta;
    std::vector<const Frustum*> m_cutting;      // the frusta the current box crosses
    convex::Polygon m_face, m_clipped;
    std::vector<glm::dvec3> m_points;
    bool m_whole = false;
};

} // namespace shadowlab
