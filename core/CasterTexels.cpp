#include "CasterTexels.h"

#include "ConvexClipping.h"
#include "JoinOverlapping.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>

namespace shadowlab {

namespace {

// Widens [lo, hi] by the images of `points`; false where one lies at or behind a perspective
// light's plane, whose image is not a point of the map.
bool growImage(const convex::Polygon& points, const glm::dmat4& shadowMatrix, glm::dvec2& lo, glm::dvec2& hi)
{
    for (const glm::dvec3& c : points) {
        const glm::dvec4 p = shadowMatrix * glm::dvec4(c, 1.0);
        if (!(p.w > 1e-9))
            return false;
        lo = glm::min(lo, glm::dvec2(p) / p.w);
        hi = glm::max(hi, glm::dvec2(p) / p.w);
    }
    return true;
}

using UvBounds = std::optional<std::pair<glm::dvec2, glm::dvec2>>;

// [lo, hi] where some of it lies inside the view's square, nothing otherwise.
UvBounds insideSquare(const glm::dvec2& lo, const glm::dvec2& hi)
{
    if (!(lo.x <= hi.x && lo.y <= hi.y) || hi.x < 0.0 || hi.y < 0.0 || lo.x > 1.0 || lo.y > 1.0)
        return std::nullopt;
    if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y))
        return std::pair{glm::dvec2(0.0), glm::dvec2(1.0)};
    return std::pair{lo, hi};
}

constexpr glm::dvec2 kEmptyLo(std::numeric_limits<double>::max());
constexpr glm::dvec2 kEmptyHi(std::numeric_limits<double>::lowest());

// The bounds in map uv of a convex region's image (its faces), past the view's square too; the
// whole square where the region reaches around the light, nothing where it lies wholly behind
// it. A region that reaches behind a perspective light is clipped to the four side planes
// first, whose apex is the light.
std::optional<std::pair<glm::dvec2, glm::dvec2>> unclippedImage(const std::vector<convex::Polygon>& faces, const LightFrame& view)
{
    glm::dvec2 lo = kEmptyLo, hi = kEmptyHi;
    bool inFront = true;
    for (const convex::Polygon& face : faces)
        inFront = inFront && growImage(face, view.shadowMatrix, lo, hi);
    if (!inFront) {
        const std::array<convex::Plane, 6> frustum = convex::frustumPlanes(view.viewProjection);
        lo = kEmptyLo;
        hi = kEmptyHi;
        for (const convex::Polygon& face : convex::clipFaces(faces, {frustum[0], frustum[1], frustum[2], frustum[3]})) {
            if (!growImage(face, view.shadowMatrix, lo, hi))
                return std::pair{glm::dvec2(0.0), glm::dvec2(1.0)};   // the light inside it
        }
    }
    if (!(lo.x <= hi.x && lo.y <= hi.y))
        return std::nullopt;
    if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y))
        return std::pair{glm::dvec2(0.0), glm::dvec2(1.0)};
    return std::pair{lo, hi};
}

// ... only where some of it lies inside the view's sides.
UvBounds faceImage(const std::vector<convex::Polygon>& faces, const LightFrame& view)
{
    const auto image = unclippedImage(faces, view);
    return image ? insideSquare(image->first, image->second) : std::nullopt;
}

// The same for a box, its corners as Bounds::corners(): those all in front of the light project
// as they are (the image of the clipped box is their hull, cut to the square).
UvBounds imageBounds(const std::array<glm::dvec3, 8>& corners, const LightFrame& view)
{
    glm::dvec2 lo = kEmptyLo, hi = kEmptyHi;
    if (growImage(convex::Polygon(corners.begin(), corners.end()), view.shadowMatrix, lo, hi))
        return insideSquare(lo, hi);
    return faceImage(convex::hexahedronFaces(corners), view);
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
        result.pieces.push_back(rect);
    }
    return result;
}

void CasterTexels::add(const CasterTexels& other)
{
    drawn |= other.drawn;
    pieces.insert(pieces.end(), other.pieces.begin(), other.pieces.end());
}

std::vector<QRect> joinOverlapping(const std::vector<QRect>& rects, std::size_t most)
{
    std::vector<QRect> drawn;
    std::copy_if(rects.begin(), rects.end(), std::back_inserter(drawn), [](const QRect& r) { return !r.isEmpty(); });
    return joinOverlapping(std::move(drawn), most, [](const QRect& a, const QRect& b) { return a.intersects(b); }, [](QRect& a, const QRect& b) { a |= b; });
}

std::vector<QRect> aroundCasters(const CasterTexels& texels, int margin, const QRect& within, std::size_t most)
{
    std::vector<QRect> grown;
    grown.reserve(texels.pieces.size());
    for (const QRect& piece : texels.pieces)
        grown.push_back(piece.adjusted(-margin, -margin, margin, margin) & within);
    return joinOverlapping(grown, most);
}

QRect readTexels(const LightFrame& view, int mapSize, const CameraFrame& camera, const Bounds& receivers, double margin)
{
    if (receivers.isEmpty() || mapSize <= 0)
        return {};
    const convex::Hull seen = convex::intersect(convex::frustumHull(camera.viewProjection), convex::boxHull(receivers));
    if (seen.faces.empty())
        return {};
    // Grown before it is cut to the square: a lookup moved off a receiver outside the map
    // may land inside it.
    const auto image = unclippedImage(seen.faces, view);
    if (!image)
        return {};
    const double grow = std::ceil(std::clamp(margin, 0.0, double(mapSize))) / double(mapSize);
    const UvBounds bounds = insideSquare(image->first - grow, image->second + grow);
    return bounds ? texelRect(bounds->first, bounds->second, mapSize) : QRect();
}

std::optional<QRect> windowPixels(const Bounds& box, const glm::dmat4& viewProjection, QSize size)
{
    if (box.isEmpty() || size.isEmpty())
        return QRect();
    if (isOutsideFrustum(viewProjection, box, false))
        return QRect();
    glm::dvec2 lo = kEmptyLo, hi = kEmptyHi;
    for (const glm::dvec3& corner : box.corners()) {
        const glm::dvec4 p = viewProjection * glm::dvec4(corner, 1.0);
        if (!(p.w > 1e-9))
            return std::nullopt;
        lo = glm::min(lo, glm::dvec2(p) / p.w);
        hi = glm::max(hi, glm::dvec2(p) / p.w);
    }
    if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y))
        return std::nullopt;
    const glm::dvec2 pixels(size.width(), size.height());
    const glm::dvec2 a = glm::clamp(glm::floor((lo * 0.5 + 0.5) * pixels) - 1.0, glm::dvec2(0.0), pixels);
    const glm::dvec2 b = glm::clamp(glm::ceil((hi * 0.5 + 0.5) * pixels) + 1.0, glm::dvec2(0.0), pixels);
    return b.x > a.x && b.y > a.y ? QRect(int(a.x), int(a.y), int(b.x - a.x), int(b.y - a.y)) : QRect();
}

} // namespace shadowlab
