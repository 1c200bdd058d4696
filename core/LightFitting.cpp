#include "LightFitting.h"

#include "ConvexClipping.h"
#include "LightMath.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace shadowlab {

using namespace convex;

namespace {

// Receivers lit without a shadow test: the share of the visible receivers' surface outside
// `volume` (a view-projection), and a warning naming the plane that cuts the most of it.
struct Cut {
    double share = 0.0;
    std::array<double, 6> byPlane{};    // share outside each of left, right, bottom, top, near, far
};

Cut measureCut(const std::vector<FitObject>& objects, const std::vector<glm::dmat4>& seen, const glm::dmat4& volume)
{
    std::vector<Plane> seenPlanes;
    for (const glm::dmat4& m : seen) {
        const std::array<Plane, 6> p = frustumPlanes(m);
        seenPlanes.insert(seenPlanes.end(), p.begin(), p.end());
    }
    const std::array<Plane, 6> volumePlanes = frustumPlanes(volume);
    double total = 0.0, inside = 0.0;
    std::array<double, 6> outside{};
    for (const FitObject& object : objects) {
        if (!object.receives || object.bounds.isEmpty())
            continue;
        const std::vector<Polygon> visible = clipFaces(hexahedronFaces(object.bounds.corners()), seenPlanes);
        total += area(visible);
        inside += area(clipFaces(visible, {volumePlanes.begin(), volumePlanes.end()}));
        for (std::size_t k = 0; k < volumePlanes.size(); ++k)
            outside[k] += area(clipFaces(visible, {Plane{-volumePlanes[k].n, -volumePlanes[k].d}}));
    }
    Cut cut;
    if (total > 0.0) {
        cut.share = std::clamp(1.0 - inside / total, 0.0, 1.0);
        for (std::size_t k = 0; k < outside.size(); ++k)
            cut.byPlane[k] = std::clamp(outside[k] / total, 0.0, 1.0);
    }
    return cut;
}

// Below this share a cut is rounding, not something to tell anyone about.
constexpr double kCutWorthSaying = 1e-3;

// Texels of margin on each side of the fitted map: wide filters near its edge still read
// texels of the region, not the border.
constexpr double kMarginTexels = 4.0;

// Steps of 2^(1/4): coarse enough that a moving camera rarely crosses one, fine enough to
// waste at most 19 % of the texels.
constexpr double kStepsPerOctave = 4.0;

// Boxes (light space, x and y) in a uniform grid of about one cell per box, for finding the
// boxes that overlap a query box without testing all of them.
class ReceiverGrid {
public:
    ReceiverGrid(const std::vector<Bounds>& boxes, const Bounds& region) : m_stamp(boxes.size(), 0)
    {
        const std::size_t count = std::size_t(std::count_if(boxes.begin(), boxes.end(), [](const Bounds& b) { return !b.isEmpty(); }));
        m_cells = std::clamp(int(std::ceil(std::sqrt(double(count)))), 1, 256);
        m_min = glm::dvec2(region.min);
        const glm::dvec2 span = glm::max(glm::dvec2(region.max) - m_min, glm::dvec2(1e-300));
        m_scale = double(m_cells) / span;
        // Each cell's boxes, in one list: counted, then placed (cell c holds m_boxes[m_start[c],
        // m_start[c + 1])).
        m_start.assign(std::size_t(m_cells * m_cells) + 1, 0);
        forEachCell(boxes, [this](std::size_t cell, std::size_t) { ++m_start[cell + 1]; });
        for (std::size_t c = 1; c < m_start.size(); ++c)
            m_start[c] += m_start[c - 1];
        m_boxes.resize(m_start.back());
        std::vector<std::size_t> next(m_start.begin(), m_start.end() - 1);
        forEachCell(boxes, [this, &next](std::size_t cell, std::size_t i) { m_boxes[next[cell]++] = i; });
    }

    // The boxes whose cells overlap `box`, each once.
    void query(const Bounds& box, std::vector<std::size_t>& out) const
    {
        out.clear();
        ++m_query;
        const auto [lo, hi] = cellRange(box);
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) {
                const std::size_t cell = std::size_t(y * m_cells + x);
                for (std::size_t k = m_start[cell]; k < m_start[cell + 1]; ++k) {
                    const std::size_t i = m_boxes[k];
                    if (m_stamp[i] != m_query) {
                        m_stamp[i] = m_query;
                        out.push_back(i);
                    }
                }
            }
        }
    }

private:
    // f(cell, box) for every cell each non-empty box overlaps.
    template<typename F>
    void forEachCell(const std::vector<Bounds>& boxes, F f) const
    {
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (boxes[i].isEmpty())
                continue;
            const auto [lo, hi] = cellRange(boxes[i]);
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    f(std::size_t(y * m_cells + x), i);
        }
    }

    std::pair<glm::ivec2, glm::ivec2> cellRange(const Bounds& b) const
    {
        const auto cell = [this](double v, int axis) {
            const double c = std::floor((v - m_min[axis]) * m_scale[axis]);
            return int(std::clamp(std::isfinite(c) ? c : 0.0, 0.0, double(m_cells - 1)));
        };
        return {{cell(b.min.x, 0), cell(b.min.y, 1)}, {cell(b.max.x, 0), cell(b.max.y, 1)}};
    }

    int m_cells = 1;
    glm::dvec2 m_min{0.0};
    glm::dvec2 m_scale{1.0};
    std::vector<std::size_t> m_start;   // per cell, where its boxes start in m_boxes; one more at the end
    std::vector<std::size_t> m_boxes;
    mutable std::vector<unsigned> m_stamp;
    mutable unsigned m_query = 0;
};

double ladderUp(double x) { return std::exp2(std::ceil(std::log2(x) * kStepsPerOctave) / kStepsPerOctave); }
double ladderDown(double x) { return std::exp2(std::floor(std::log2(x) * kStepsPerOctave) / kStepsPerOctave); }

} // namespace

namespace {

// Light space of a fit: x and y across the map (tangents of the angle for a perspective light),
// and distance from the anchor along the direction.
struct LightSpace {
    glm::dmat4 view;
    bool perspective = false;
    glm::dvec3 operator()(const glm::dvec3& p) const
    {
        const glm::dvec3 v(view * glm::dvec4(p, 1.0));
        const double depth = -v.z;
        return perspective ? glm::dvec3(v.x / depth, v.y / depth, depth) : glm::dvec3(v.x, v.y, depth);
    }
    // The bounds of a whole box in light space, the same as its corners': an ortho light's, affine,
    // from the two corners each axis's row picks (coordinateRange), not all eight through the
    // view; a perspective light's through its corners.
    Bounds boundsOf(const Bounds& box) const
    {
        Bounds b;
        if (box.isEmpty())
            return b;
        if (perspective) {
            for (const glm::dvec3& c : box.corners())
                b.extend((*this)(c));
            return b;
        }
        for (int axis = 0; axis < 3; ++axis) {
            const auto [least, greatest] = coordinateRange(view, axis, box);
            b.min[axis] = axis == 2 ? -greatest : least;    // depth is -z
            b.max[axis] = axis == 2 ? -least : greatest;
        }
        return b;
    }
};

// What can be seen: each receiver's part inside the camera (and the cone), in light space, and
// the region they span.
struct SeenParts {
    std::vector<Bounds> parts;
    Bounds region;
    double nearDepth = 0.0, farDepth = 0.0;     // their view depths (clip w of `camera`)
};

SeenParts seenParts(const std::vector<FitObject>& objects, const std::vector<glm::dmat4>& limits, const LightSpace& toLight,
                    const std::optional<glm::dmat4>& camera, std::vector<glm::dvec2>* lightPoints)
{
    SeenParts seen;
    seen.parts.resize(objects.size());
    double nearest = 1e300, farthest = 0.0;
    FrustaClip clip(limits);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!objects[i].receives)
            continue;
        const std::vector<glm::dvec3>& points = clip(objects[i].bounds);  // nothing where it lies outside a limit
        if (clip.whole() && !lightPoints) {
            // Most of a large scene: the whole box, without its corners one by one.
            seen.parts[i] = toLight.boundsOf(objects[i].bounds);
            if (camera) {
                const auto [low, high] = coordinateRange(*camera, 3, objects[i].bounds);    // clip w
                nearest = std::min(nearest, low);
                farthest = std::max(farthest, high);
            }
            seen.region.extend(seen.parts[i]);
            continue;
        }
        for (const glm::dvec3& p : points) {
            const glm::dvec3 l = toLight(p);
            seen.parts[i].extend(l);
            if (lightPoints)
                lightPoints->emplace_back(l);
            if (camera) {
                const double w = ((*camera) * glm::dvec4(p, 1.0)).w;
                nearest = std::min(nearest, w);
                farthest = std::max(farthest, w);
            }
        }
        seen.region.extend(seen.parts[i]);
    }
    if (farthest > 0.0 && std::isfinite(farthest)) {
        seen.nearDepth = std::max(nearest, 0.0);
        seen.farDepth = farthest;
    }
    return seen;
}

// Where casters fall over the receivers seen, in light space (x and y), and the prism they
// were clipped to: each caster's part over the region, in front of its far side.
struct CasterFootprint {
    Bounds footprint;
    double casterStart = 0.0;   // the prism's near side
    double regionFar = 0.0;     // ... and its far side
};

CasterFootprint casterFootprint(const std::vector<FitObject>& objects, const std::vector<Bounds>& seen, const Bounds& region,
                                const LightSpace& toLight)
{
    const bool perspective = toLight.perspective;
    const glm::dmat4& view = toLight.view;
    // (A perspective prism starts a millionth of the way out: closer, its far plane, taken back
    // out of the matrix, would move by more than the margin below.)
    double casterStart = perspective ? region.max.z * 1e-6 : region.min.z;
    if (!perspective) {
        for (const FitObject& object : objects) {
            if (object.casts && !object.bounds.isEmpty())
                casterStart = std::min(casterStart, toLight.boundsOf(object.bounds).min.z - 1.0);
        }
    }
    const double regionFar = region.max.z + std::abs(region.max.z) * 1e-6 + 1e-12;
    const glm::dmat4 prism = perspective
        ? glm::frustum(region.min.x * casterStart, region.max.x * casterStart, region.min.y * casterStart, region.max.y * casterStart,
                       casterStart, regionFar) * view
        : glm::ortho(region.min.x, region.max.x, region.min.y, region.max.y, casterStart, regionFar) * view;
    std::vector<Bounds> casterParts(objects.size());
    FrustaClip clip({prism});
    for (std::size_t j = 0; j < objects.size(); ++j) {
        if (objects[j].casts && isFinite(prism)) {
            const std::vector<glm::dvec3>& points = clip(objects[j].bounds);
            if (clip.whole())
                casterParts[j] = toLight.boundsOf(objects[j].bounds);
            else {
                for (const glm::dvec3& p : points)
                    casterParts[j].extend(toLight(p));
            }
        }
    }

    // The map covers where a caster's part lies over a receiver's part that is behind it: the
    // shadow of a caster falls at its own place in light space.
    // Receivers go into a grid over the region, so each caster meets only the receivers near
    // it: a city's thousands of objects pair in about linear time, not quadratic.
    const ReceiverGrid receiverGrid(seen, region);
    Bounds footprint;
    std::vector<std::size_t> near;
    for (std::size_t j = 0; j < objects.size(); ++j) {
        const Bounds& c = casterParts[j];
        if (c.isEmpty())
            continue;
        // Nothing to add when the footprint holds the caster's whole part already.
        if (!footprint.isEmpty() && c.min.x >= footprint.min.x && c.min.y >= footprint.min.y && c.max.x <= footprint.max.x
            && c.max.y <= footprint.max.y)
            continue;
        receiverGrid.query(c, near);
        for (std::size_t i : near) {
            const Bounds& r = seen[i];
            if (r.isEmpty() || (i == j && objects[j].convex) || !(r.max.z > c.min.z))
                continue;
            const glm::dvec2 low = glm::max(glm::dvec2(c.min), glm::dvec2(r.min));
            const glm::dvec2 high = glm::min(glm::dvec2(c.max), glm::dvec2(r.max));
            if (low.x <= high.x && low.y <= high.y) {
                footprint.extend(glm::dvec3(low, 0.0));
                footprint.extend(glm::dvec3(high, 0.0));
            }
        }
    }
    return {footprint, casterStart, regionFar};
}

// The map's window over the footprint: its centre and span in light space (x and y) with a
// margin of texels, stabilised to whole texels and coarse steps of size when asked; `grid` is
// the step the depth range snaps to then (ortho, world units).
struct MapWindow {
    glm::dvec2 centre{0.0};
    glm::dvec2 span{0.0};
    double grid = 0.0;
};

MapWindow mapWindow(const Bounds& footprint, double regionSpan, int mapSize, bool stabilize)
{
    const double texels = double(mapSize);
    MapWindow w;
    w.centre = (glm::dvec2(footprint.min) + glm::dvec2(footprint.max)) * 0.5;
    w.span = glm::dvec2(footprint.max) - glm::dvec2(footprint.min);
    w.span = glm::max(w.span, glm::dvec2(std::max({w.span.x, w.span.y, regionSpan}) * 1e-3));
    w.span *= texels / std::max(texels - 2.0 * kMarginTexels, texels * 0.5);
    if (stabilize) {
        // Whole texels, and coarse steps of size: the snapped centre moves by up to a sixteenth.
        for (int a = 0; a < 2; ++a) {
            w.span[a] = ladderUp(w.span[a] * 16.0 / 15.0);
            const double step = w.span[a] / texels * std::max(1.0, std::floor(texels / 16.0));
            w.centre[a] = std::round(w.centre[a] / step) * step;
            w.grid = std::max(w.grid, step);
        }
    }
    return w;
}

// The light-space depths of the receivers seen under the window (casters in front of it are
// clamped to the near plane by the depth pass and still cast).
Bounds windowDepths(const std::vector<FitObject>& objects, const std::vector<Bounds>& seen, const std::vector<glm::dmat4>& limits,
                    const MapWindow& w, const CasterFootprint& casters, const Bounds& region, const LightSpace& toLight)
{
    const glm::dvec2 low = w.centre - w.span * 0.5, high = w.centre + w.span * 0.5;
    const double casterStart = casters.casterStart, regionFar = casters.regionFar;
    const glm::dmat4 column = toLight.perspective
        ? glm::frustum(low.x * casterStart, high.x * casterStart, low.y * casterStart, high.y * casterStart, casterStart, regionFar) * toLight.view
        : glm::ortho(low.x, high.x, low.y, high.y, region.min.z - 1.0, regionFar) * toLight.view;
    std::vector<glm::dmat4> columnLimits = limits;
    columnLimits.push_back(column);
    Bounds depths;
    FrustaClip clip(columnLimits);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (seen[i].isEmpty() || !isFinite(column))
            continue;
        // Well inside the column, a receiver's part is the one seen (seenParts clipped it to the
        // same limits): the same points, so the same bounds.
        if (frustumSide(objects[i].bounds, column) == FrustumSide::WellInside)
            depths.extend(seen[i]);
        else {
            for (const glm::dvec3& p : clip(objects[i].bounds))
                depths.extend(toLight(p));
        }
    }
    return depths.isEmpty() ? region : depths;
}

// The volume of the window and depths: a perspective light's frustum from its position, or an
// ortho box centred on its own origin.
LightVolume windowVolume(const LightSettings& light, const LightVolume& manual, const glm::dvec3& anchor, const glm::dmat4& view,
                         const MapWindow& w, const Bounds& depths)
{
    LightVolume fitted;
    fitted.direction = manual.direction;
    fitted.perspective = manual.perspective;
    const double depthSpan = depths.max.z - depths.min.z;
    if (manual.perspective) {
        const double t = std::tan(glm::radians(kMaxFittedFov) * 0.5);
        fitted.left = std::max(w.centre.x - w.span.x * 0.5, -t);
        fitted.right = std::min(w.centre.x + w.span.x * 0.5, t);
        fitted.bottom = std::max(w.centre.y - w.span.y * 0.5, -t);
        fitted.top = std::min(w.centre.y + w.span.y * 0.5, t);
        double nearPlane = std::max(depths.min.z * (1.0 - 1e-3), depths.max.z * 1e-4);
        double farPlane = depths.max.z * (1.0 + 1e-3) + 1e-12;
        if (light.stabilize) {
            nearPlane = ladderDown(nearPlane);
            farPlane = ladderUp(farPlane);
        }
        fitted.origin = light.position;
        fitted.nearPlane = nearPlane;
        fitted.farPlane = std::max(farPlane, nearPlane * (1.0 + 1e-6));
        return fitted;
    }
    const double margin = depthSpan * 1e-3 + std::max(w.span.x, w.span.y) * 1e-3;
    double nearPlane = depths.min.z - margin;
    double farPlane = depths.max.z + margin;
    if (w.grid > 0.0) {
        nearPlane = std::floor(nearPlane / w.grid) * w.grid;
        farPlane = std::ceil(farPlane / w.grid) * w.grid;
    }
    // Centre the volume on its own origin: the matrices then hold small numbers however far
    // the scene is from the target, and float keeps its precision.
    const double middle = (nearPlane + farPlane) * 0.5;
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    fitted.origin = anchor + right * w.centre.x + up * w.centre.y + manual.direction * middle;
    fitted.left = -w.span.x * 0.5;
    fitted.right = w.span.x * 0.5;
    fitted.bottom = -w.span.y * 0.5;
    fitted.top = w.span.y * 0.5;
    fitted.nearPlane = nearPlane - middle;
    fitted.farPlane = farPlane - middle;
    return fitted;
}

} // namespace

FittedLight fitLight(const LightSettings& light, const std::vector<FitObject>& objects, const std::optional<glm::dmat4>& camera,
                     int mapSize, const std::vector<glm::dmat4>& within, const glm::dvec3& mapUp)
{
    FittedLight result;
    const LightVolume manual = manualVolume(light);
    const double distance = glm::length(light.position - light.target);
    result.volume = manual;
    result.texelBefore = result.texelAfter = texelWorldSize(manual, mapSize, distance);
    result.anythingToShadow = std::any_of(objects.begin(), objects.end(), [](const FitObject& o) { return o.casts && !o.bounds.isEmpty(); });

    std::vector<glm::dmat4> seen;
    if (camera)
        seen.push_back(*camera);
    seen.insert(seen.end(), within.begin(), within.end());

    if (light.fit == LightFit::Manual) {
        const Cut cut = measureCut(objects, seen, computeLightFrame(light, manual).viewProjection);
        result.cutShare = cut.share;
        if (cut.share > kCutWorthSaying && result.anythingToShadow)
            result.cuts.push_back({.by = FitCut::By::ManualVolume, .perspective = manual.perspective, .share = cut.share, .byPlane = cut.byPlane});
        return result;
    }

    const bool perspective = manual.perspective;
    // A directional light's volume hangs off its target, so its distance changes nothing.
    const glm::dvec3 anchor = perspective ? light.position : light.target;
    const glm::dvec3 up = perspective ? glm::dvec3(0.0) : mapUp;
    const LightSpace toLight{stableLookAlong(anchor, manual.direction, up), perspective};

    double reach = 0.0;     // from the anchor to the farthest corner of anything
    for (const FitObject& object : objects) {
        if (!object.bounds.isEmpty()) {
            for (const glm::dvec3& c : object.bounds.corners())
                reach = std::max(reach, glm::length(c - anchor));
        }
    }
    std::vector<glm::dmat4> limits = seen;
    if (perspective) {
        // One map covers at most a cone of kMaxFittedFov in front of the light.
        const double t = std::tan(glm::radians(kMaxFittedFov) * 0.5);
        const double farthest = 2.0 * reach + 1.0;
        const double n = farthest * 1e-9;
        limits.push_back(glm::frustum(-t * n, t * n, -t * n, t * n, n, farthest) * toLight.view);
        const Cut cut = measureCut(objects, seen, limits.back());
        result.cutShare = cut.share;
        if (cut.share > kCutWorthSaying && result.anythingToShadow)
            result.cuts.push_back({.by = FitCut::By::WidestCone, .perspective = true, .share = cut.share, .byPlane = cut.byPlane});
    }

    // A warped map covers only the receivers' outline, not its box (LightVolume::up is set for it).
    std::vector<glm::dvec2> outline;
    SeenParts visible = seenParts(objects, limits, toLight, camera, up != glm::dvec3(0.0) ? &outline : nullptr);
    result.seenNearDepth = visible.nearDepth;
    result.seenFarDepth = visible.farDepth;
    Bounds& region = visible.region;
    if (region.isEmpty()) {
        result.anythingToShadow = false;
        return result;
    }
    // A region of zero width (a receiver seen edge-on) still makes a prism.
    const double regionSpan = std::max({region.max.x - region.min.x, region.max.y - region.min.y, perspective ? 1e-9 : reach * 1e-9, 1e-12});
    region.min -= glm::dvec3(regionSpan * 1e-6, regionSpan * 1e-6, 0.0);
    region.max += glm::dvec3(regionSpan * 1e-6, regionSpan * 1e-6, 0.0);

    const CasterFootprint casters = casterFootprint(objects, visible.parts, region, toLight);
    if (casters.footprint.isEmpty()) {
        result.anythingToShadow = false;
        return result;
    }
    const MapWindow window = mapWindow(casters.footprint, regionSpan, mapSize, light.stabilize);
    const Bounds depths = windowDepths(objects, visible.parts, limits, window, casters, region, toLight);
    result.volume = windowVolume(light, manual, anchor, toLight.view, window, depths);
    result.volume.up = up;
    if (!outline.empty())
        result.focus = focusOutline(std::move(outline), window.centre, window.span, kMarginTexels * std::max(window.span.x, window.span.y) / mapSize);
    result.fitted = true;
    result.texelAfter = texelWorldSize(result.volume, mapSize, distance);
    return result;
}

std::vector<glm::dvec2> cameraFootprint(const Bounds& box, const glm::dmat4& cameraViewProjection, const glm::dmat4& shadowMatrix)
{
    std::vector<glm::dvec2> points;
    for (const glm::dvec3& p : clipBoxToFrusta(box, {cameraViewProjection})) {
        const glm::dvec4 t = shadowMatrix * glm::dvec4(p, 1.0);
        if (t.w > 1e-12)
            points.emplace_back(t.x / t.w, t.y / t.w);
    }
    if (points.size() < 3)
        return {};
    return convexHull(std::move(points));
}

std::vector<glm::dvec2> focusOutline(std::vector<glm::dvec2> points, const glm::dvec2& centre, const glm::dvec2& span, double margin)
{
    const std::vector<glm::dvec2> hull = convexHull(std::move(points));
    if (hull.size() < 3)
        return {};
    glm::dvec2 centroid(0.0);
    for (const glm::dvec2& p : hull)
        centroid += p / double(hull.size());
    Polygon polygon;
    for (const glm::dvec2& p : hull) {
        const glm::dvec2 out = p - centroid;
        const double length = glm::length(out);
        polygon.emplace_back(p + (length > 0.0 ? out / length * margin : glm::dvec2(0.0)) - centre, 0.0);
    }
    const glm::dvec2 half = span * 0.5;
    for (const Plane& side : {Plane{{1, 0, 0}, half.x}, Plane{{-1, 0, 0}, half.x}, Plane{{0, 1, 0}, half.y}, Plane{{0, -1, 0}, half.y}}) {
        polygon = clip(polygon, side);
        if (polygon.empty())
            return {};
    }
    std::vector<glm::dvec2> focus;
    for (const glm::dvec3& p : polygon)
        focus.emplace_back(p);
    return focus.size() >= 3 ? focus : std::vector<glm::dvec2>{};
}

std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points)
{
    if (points.size() < 3)
        return points;
    // Andrew's monotone chain.
    std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k > 0 ? k - 1 : 0);
    return hull;
}

} // namespace shadowlab
