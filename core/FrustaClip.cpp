#include "FrustaClip.h"

#include "LightMath.h"

#include <glm/geometric.hpp>

#include <utility>

namespace shadowlab {

using namespace convex;

FrustumSide frustumSide(const Bounds& box, const glm::dmat4& viewProjection)
{
    // Each clip-space bound is an affine function of the point.
    const BoxExtent extent(box);
    const glm::dvec4 w = matrixRow(viewProjection, 3);
    bool wellInside = extent.least(w) > 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const glm::dvec4 r = matrixRow(viewProjection, axis);
        for (const double side : {1.0, -1.0}) {
            // Outside: w + side * r < 0 at every point. Well inside: (1 - 1e-9) w - side * r > 0 at
            // every point.
            if (extent.greatest(w + side * r) < 0.0)
                return FrustumSide::Outside;
            wellInside = wellInside && extent.least(w * (1.0 - 1e-9) - side * r) > 0.0;
        }
    }
    return wellInside ? FrustumSide::WellInside : FrustumSide::Across;
}

std::pair<double, double> coordinateRange(const glm::dmat4& m, int i, const Bounds& box)
{
    const auto at = [&](bool greatest) {
        glm::dvec3 c;
        for (int axis = 0; axis < 3; ++axis)
            c[axis] = (m[axis][i] >= 0.0) == greatest ? box.max[axis] : box.min[axis];
        return (m[0][i] * c.x + m[1][i] * c.y) + (m[2][i] * c.z + m[3][i] * 1.0);
    };
    return {at(false), at(true)};
}

FrustaClip::FrustaClip(const std::vector<glm::dmat4>& viewProjections)
{
    m_frusta.reserve(viewProjections.size());
    for (const glm::dmat4& m : viewProjections)
        m_frusta.push_back({m, {}, {}});
}

const std::vector<glm::dvec3>& FrustaClip::operator()(const Bounds& box)
{
    m_points.clear();
    m_whole = false;
    if (box.isEmpty())
        return m_points;
    // Most boxes of a large scene lie wholly inside the frusta, or wholly outside one: the clip
    // is then the box itself, or nothing.
    const std::array<glm::dvec3, 8> corners = box.corners();
    m_cutting.clear();
    for (Frustum& frustum : m_frusta) {
        const FrustumSide side = frustumSide(box, frustum.viewProjection);
        if (side == FrustumSide::Outside) {
            m_cutting.clear();
            return m_points;
        }
        if (side == FrustumSide::WellInside)
            continue;
        if (frustum.faces.empty()) {
            frustum.faces = hexahedronFaces(frustumCorners(frustum.viewProjection));
            frustum.planes = frustumPlanes(frustum.viewProjection);
        }
        m_cutting.push_back(&frustum);
    }
    if (m_cutting.empty()) {
        m_whole = true;
        m_points.assign(corners.begin(), corners.end());
        return m_points;
    }
    const std::array<Plane, 6> planes = boxPlanes(box);     // boxHull's, in its order
    for (const std::array<int, 4>& face : kHexahedronFaces) {
        m_face.clear();
        for (int corner : face)
            m_face.push_back(corners[std::size_t(corner)]);
        appendClipped(0, planes);
    }
    for (std::size_t k = 0; k < m_cutting.size(); ++k) {
        for (const Polygon& face : m_cutting[k]->faces) {
            m_face.assign(face.begin(), face.end());
            appendClipped(k + 1, planes);
        }
    }
    return m_points;
}

void FrustaClip::appendClipped(std::size_t own, const std::array<Plane, 6>& boxSides)
{
    const auto clipBy = [this](const Plane& plane) {
        clipInto(m_face, plane, m_clipped);
        std::swap(m_face, m_clipped);
        return !m_face.empty();
    };
    for (std::size_t source = 0; source <= m_cutting.size(); ++source) {
        if (source == own)
            continue;
        for (const Plane& plane : source == 0 ? boxSides : m_cutting[source - 1]->planes) {
            if (!clipBy(plane))
                return;
        }
    }
    m_points.insert(m_points.end(), m_face.begin(), m_face.end());
}

std::vector<glm::dvec3> clipBoxToFrusta(const Bounds& box, const std::vector<glm::dmat4>& viewProjections)
{
    return FrustaClip(viewProjections)(box);
}

} // namespace shadowlab
