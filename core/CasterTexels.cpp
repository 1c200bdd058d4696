#include "CasterTexels.h"

#include "ConvexClipping.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// The bounds in map uv of a box's image, or nothing where none of it lies inside the view's
// sides. Corners all in front of the light project as they are (the image of the clipped box
// is their hull, cut to the square); a box that reaches behind a perspective light is clipped
// to the four side planes first, whose apex is the light: a box around the light covers all.
std::optional<std::pair<glm::dvec2, glm::dvec2>> imageBounds(const std::array<glm::dvec3, 8>& corners, const LightFrame& view)
{
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    bool inFront = true;
    for (const glm::dvec3& c : corners) {
        const glm::dvec4 p = view.shadowMatrix * glm::dvec4(c, 1.0);
        if (!(p.w > 1e-9)) {
            inFront = false;
            break;
        }
        lo = glm::min(lo, glm::dvec2(p) / p.w);
        hi = glm::max(hi, glm::dvec2(p) / p.w);
    }
    if (!inFront) {
        const std::array<convex::Plane, 6> frustum = convex::frustumPlanes(view.viewProjection);
        const std::vector<convex::Polygon> clipped =
            convex::clipFaces(convex::hexahedronFaces(corners), {frustum[0], frustum[1], frustum[2], frustum[3]});
        lo = glm::dvec2(std::numeric_limits<double>::max());
        hi = glm::dvec2(std::numeric_limits<double>::lowest());
        for (const convex::Polygon& face : clipped) {
            for (const glm::dvec3& c : face) {
                const glm::dvec4 p = view.shadowMatrix * glm::dvec4(c, 1.0);
                if (!(p.w > 1e-9))
                    return std::pair{glm::dvec2(0.0), glm::dvec2(1.0)};   // the light inside it
                lo = glm::min(lo, glm::dvec2(p) / p.w);
                hi = glm::max(hi, glm::dvec2(p) / p.w);
            }
        }
    }
    if (!(lo.x <= hi.x && lo.y <= hi.y) || hi.x < 0.0 || hi.y < 0.0 || lo.x > 1.0 || lo.y > 1.0)
        return std::nullopt;
    if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y))
        return std::pair{glm::dvec2(0.0), glm::dvec2(1.0)};
    return std::pair{lo, hi};
}

QRect texelRect(const glm::dvec2& lo, const glm::dvec2& hi, int mapSize)
{
    // A texel is drawn when its centre is covered: the one the edge crosses, and one more for
    // the rasteriser's rounding of the vertices.
    const double size = double(mapSize);
    const int x0 = int(std::clamp(std::floor(lo.x * size) - 1.0, 0.0, size));
    const int y0 = int(std::clamp(std::floor(lo.y * size) - 1.0, 0.0, size));
    const int x1 = int(std::clamp(std::ceil(hi.x * size) + 1.0, 0.0, size));
    const int y1 = int(std::clamp(std::ceil(hi.y * size) + 1.0, 0.0, size));
    return x1 > x0 && y1 > y0 ? QRect(x0, y0, x1 - x0, y1 - y0) : QRect();
}

} // namespace

CasterTexels casterTexels(const LightFrame& view, int mapSize, const std::vector<ReachObject>& casters)
{
    CasterTexels result;
    for (const ReachObject& object : casters) {
        if (!object.casts || object.bounds.isEmpty() || culledFrom(object, view))
            continue;
        const auto bounds = imageBounds(object.box ? *object.box : object.bounds.corners(), view);
        if (!bounds)
            continue;
        const QRect rect = texelRect(bounds->first, bounds->second, mapSize);
        if (rect.isEmpty())
            continue;
        result.drawn |= rect;
    }
    return result;
}

} // namespace shadowlab
