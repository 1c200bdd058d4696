#include "ShadowReach.h"

#include "JoinOverlapping.h"
#include "ShadowTechnique.h"

#include <glm/common.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowlab {

namespace {

// A box's image in a view's texture space: xy and depth bounds of its corners and the uv of
// each, or nothing when it lies wholly behind a perspective light (where every receiver is
// lit). `straddles` when some corners are behind and some in front: its image is then unbounded.
struct TextureFootprint {
    bool empty = true;
    bool straddles = false;
    glm::dvec3 min{0.0}, max{0.0};
    std::array<glm::dvec2, 8> points{};  // the corners' uv, those in front of the light
    int pointCount = 0;
};

TextureFootprint footprint(const std::array<glm::dvec3, 8>& corners, const glm::dmat4& shadowMatrix)
{
    TextureFootprint f;
    int behind = 0;
    Bounds image;
    for (const glm::dvec3& corner : corners) {
        const glm::dvec4 p = shadowMatrix * glm::dvec4(corner, 1.0);
        if (p.w <= 1e-12) {
            ++behind;
            continue;
        }
        image.extend(glm::dvec3(p) / p.w);
        f.points[std::size_t(f.pointCount++)] = glm::dvec2(p.x / p.w, p.y / p.w);
    }
    if (behind == 8)
        return f;
    f.empty = false;
    f.straddles = behind > 0;
    f.min = image.min;
    f.max = image.max;
    return f;
}

TextureFootprint footprint(const Bounds& bounds, const glm::dmat4& shadowMatrix)
{
    return bounds.isEmpty() ? TextureFootprint{} : footprint(bounds.corners(), shadowMatrix);
}

// An object's image: its own box's where known, its bounds' otherwise.
TextureFootprint imageOf(const ReachObject& object, const glm::dmat4& shadowMatrix)
{
    return object.box && !object.bounds.isEmpty() ? footprint(*object.box, shadowMatrix) : footprint(object.bounds, shadowMatrix);
}

// The convex hull of `points`, counter-clockwise, without collinear points (Andrew's
// monotone chain); fewer than three points where they do not span an area.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points)
{
    std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return {};
    const auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    for (const glm::dvec2& p : points) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0.0)
            --k;
        hull[k++] = p;
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull.size() >= 3 ? hull : std::vector<glm::dvec2>{};
}

// The map depth (conventional, [0, 1] from near to far) of a point `distance` along a
// perspective view's axis.
double perspectiveDepthAt(const LightFrame& view, double distance)
{
    const glm::dvec4 clip = view.projection * glm::dvec4(0.0, 0.0, -distance, 1.0);
    return clip.z / clip.w * 0.5 + 0.5;
}

// No boxes: every receiver looks up, as without a reach.
ShadowReach lookupsEverywhere(const std::vector<ReachObject>& receivers)
{
    ShadowReach reach;
    for (const ReachObject& r : receivers)
        reach.objects.push_back(r.receives ? Reach::Inside : Reach::Outside);
    return reach;
}

bool finite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

bool culledFrom(const ReachObject& object, const LightFrame& view)
{
    if (!object.frontFacesCulled || !object.plane)
        return false;
    const glm::dvec3& n = object.plane->normal;
    const double scale = glm::length(object.bounds.max - object.bounds.min) + glm::length(view.position - object.plane->point);
    return view.perspective ? glm::dot(n, view.position - object.plane->point) > 1e-9 * scale : glm::dot(n, -view.direction) > 1e-9;
}

std::optional<double> tapReachTexels(const Settings& settings)
{
    const ShadowTechnique& technique = shadowTechnique(settings.filter.mode);
    std::optional<double> reach = technique.tapReach(settings.filter);
    if (technique.map == ShadowMapKind::Moments && technique.farPlaneReadsLit && !settings.moments.mipmaps && settings.moments.anisotropy <= 1)
        reach = double(std::max(settings.moments.blur - 1, 0) / 2);     // its blur, in the map or the lookup
    if (!reach)
        return std::nullopt;
    // A nearest tap may round to the neighbour, a bilinear one reads 2 x 2; and two texels of
    // margin for rounding. The normal offset is the view's own (shadowReach).
    return 1.0 + *reach + 2.0;
}

double lookupShiftTexels(const Settings& settings)
{
    return std::max(settings.bias.normal, 0.0) + (settings.bias.footprint ? 0.5 : 0.0);
}

std::optional<double> lookupReachTexels(const Settings& settings, const LightFrame& view)
{
    const std::optional<double> taps = tapReachTexels(settings);
    if (!taps)
        return std::nullopt;
    // A warped view's texels differ in shape over the map: no bound from its volume.
    if (view.volume.warped && (settings.bias.normal > 0.0 || settings.bias.footprint))
        return std::nullopt;
    if (view.perspective && settings.bias.normal > 0.0)
        return std::nullopt;
    // The offsets are in texels of the wider axis: on the narrower one as many of its own as
    // the axes' ratio. The footprint bias moves a lookup by up to half a texel.
    const double wide = std::max(view.volume.width(), view.volume.height());
    const double narrow = std::max(std::min(view.volume.width(), view.volume.height()), wide * 1e-9);
    return *taps + lookupShiftTexels(settings) * wide / narrow;
}

bool referencesStayNearer(const Settings& settings)
{
    // A negative polygon offset pulls the stored depths toward the light, past the casters'.
    if (settings.bias.polygonFactor < 0.0 || settings.bias.polygonUnits < 0.0)
        return false;
    return shadowTechnique(settings.filter.mode).referencesStayNearer(settings);
}

std::array<glm::dvec3, 8> ReachBox::worldCorners() const
{
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 texture((i & 1) ? uvMax.x : uvMin.x, (i & 2) ? uvMax.y : uvMin.y, (i & 4) ? depthMax : depthMin, 1.0);
        const glm::dvec4 world = textureToWorld * texture;
        corners[std::size_t(i)] = glm::dvec3(world) / world.w;
    }
    return corners;
}

std::vector<convex::Polygon> ReachBox::worldFaces() const
{
    convex::Polygon section{{uvMin.x, uvMin.y, 0.0}, {uvMax.x, uvMin.y, 0.0}, {uvMax.x, uvMax.y, 0.0}, {uvMin.x, uvMax.y, 0.0}};
    for (const glm::dvec3& e : uvEdges) {
        section = convex::clip(section, convex::Plane{glm::dvec3(e.x, e.y, 0.0), e.z});
        if (section.size() < 3)
            return {};
    }
    const auto world = [&](const glm::dvec3& uv, double depth) {
        const glm::dvec4 p = textureToWorld * glm::dvec4(uv.x, uv.y, depth, 1.0);
        return glm::dvec3(p) / p.w;
    };
    convex::Polygon nearCap, farCap;
    for (const glm::dvec3& c : section) {
        nearCap.push_back(world(c, depthMin));
        farCap.push_back(world(c, depthMax));
    }
    std::vector<convex::Polygon> faces;
    for (std::size_t i = 0, n = section.size(); i < n; ++i)
        faces.push_back({nearCap[i], nearCap[(i + 1) % n], farCap[(i + 1) % n], farCap[i]});
    faces.push_back(std::move(nearCap));
    faces.push_back(std::move(farCap));
    return faces;
}

int ShadowReach::outsideCount() const
{
    return int(std::count(objects.begin(), objects.end(), Reach::Outside));
}

int ShadowReach::partlyCount() const
{
    return int(std::count(objects.begin(), objects.end(), Reach::Partly));
}

namespace {

struct UvRect {
    glm::dvec2 min, max;
    double depth = 0.0;                 // the nearest caster's depth
    std::vector<glm::dvec2> points;     // its casters' corners in uv, ungrown; empty: the rectangle alone

    bool overlaps(const UvRect& o) const { return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y; }
    void extend(const UvRect& o)
    {
        min = glm::min(min, o.min);
        max = glm::max(max, o.max);
        depth = std::min(depth, o.depth);
        if (points.empty() || o.points.empty())
            points.clear();
        else
            points.insert(points.end(), o.points.begin(), o.points.end());
    }
};

// One rectangle per caster is the tightest reach; overlapping ones are merged, and past
// kMaxReachBoxes the union of all stands (a mask of thousands of columns saves nothing).
constexpr std::size_t kMaxReachBoxes = 16;

std::vector<UvRect> mergedRects(std::vector<UvRect> rects)
{
    return joinOverlapping(std::move(rects), kMaxReachBoxes, [](const UvRect& a, const UvRect& b) { return a.overlaps(b); },
                           [](UvRect& a, const UvRect& b) { a.extend(b); });
}

// The edges of the convex hull of `points` as half-planes a u + b v + c >= 0, each moved out by
// how far a rectangle of half-size `grow` reaches across it (the hull grown by the taps).
std::vector<glm::dvec3> hullEdges(const std::vector<glm::dvec2>& points, const glm::dvec2& grow)
{
    const std::vector<glm::dvec2> hull = convexHull(points);
    std::vector<glm::dvec3> edges;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i], along = hull[(i + 1) % hull.size()] - a;
        const double length = glm::length(along);
        if (!(length > 0.0))
            continue;       // leaving a cut out only widens the column
        const glm::dvec2 out = glm::dvec2(along.y, -along.x) / length;
        edges.emplace_back(-out.x, -out.y, glm::dot(out, a) + grow.x * std::abs(out.x) + grow.y * std::abs(out.y));
    }
    return edges;
}

// Whether the rectangle from `lo` to `hi` lies wholly outside one of `edges`.
bool outsideAnEdge(const std::vector<glm::dvec3>& edges, const glm::dvec2& lo, const glm::dvec2& hi)
{
    for (const glm::dvec3& e : edges) {
        // The rectangle's corner farthest inside the edge.
        const glm::dvec2 best(e.x >= 0.0 ? hi.x : lo.x, e.y >= 0.0 ? hi.y : lo.y);
        if (e.x * best.x + e.y * best.y + e.z < 0.0)
            return true;
    }
    return false;
}

// Where a box starts when a tap may compare deeper than its receiver (a receiver plane's): far
// before the near plane, since the casters clamped onto it are stored at depth 0 and a receiver
// there, itself clamped too, may still find them (a thousand times the volume's depth before
// it: a perspective light's depth falls toward minus infinity only at the light itself).
constexpr double kBeforeNear = -1e3;

// How far a view's taps reach around a caster: the taps' grow and, with a normal offset, the
// shift of each lookup off its receiver.
struct TapReach {
    std::optional<double> texels;   // none: the taps may read anywhere
    double grow = 1.0;              // the taps' reach in the map's uv
    bool nearerIsLit = true;        // receivers nearer the light than every caster read lit
};

// One view's boxes: each caster's footprint, grown by the taps' reach, within the map's square
// (outside it every tap reads the lit border). None when lookups may land anywhere.
std::optional<std::vector<ReachBox>> viewBoxes(const Settings& settings, const LightFrame& view, int mapSize,
                                               const std::vector<ReachObject>& casters, const TapReach& taps)
{
    // The normal offset moves each lookup off its receiver by up to bias.normal texels of
    // the wider axis: on the narrower one, and in depth, by that length over their spans.
    // Receivers outside the map or beyond the far plane may look up inside: the boxes grow
    // past both by as much. Off a perspective light's axis the shift has no small bound.
    glm::dvec2 offsetUv(0.0);
    double offsetDepth = 0.0;
    if (settings.bias.normal > 0.0) {
        if (view.perspective || view.volume.warped)
            return std::nullopt;      // a warped texel's size varies over the map
        const double length = settings.bias.normal * texelWorldSize(view.volume, mapSize);
        offsetUv = length / glm::max(glm::dvec2(view.volume.width(), view.volume.height()), glm::dvec2(1e-300));
        offsetDepth = length / std::max(view.volume.farPlane - view.volume.nearPlane, 1e-300);
    }
    // The far face a little beyond the far plane, for rounding: in depth for an ortho view,
    // in distance for a perspective one, whose depth reaches only just past 1 at infinity
    // (with a near plane close to the light, a depth of 1 + 1e-4 lies behind the light).
    const double farFace = view.perspective ? perspectiveDepthAt(view, view.volume.farPlane * 1.001) : 1.0 + offsetDepth + 1e-4;
    std::vector<UvRect> rects;
    bool anywhere = false;
    // Hulls where the casters are few enough to keep columns of their own; past that the union
    // of every rectangle stands, and the hull of thousands of casters is not worth its sort.
    const bool hulls = casters.size() <= 4 * kMaxReachBoxes;
    for (const ReachObject& object : casters) {
        if (!object.casts || culledFrom(object, view))
            continue;
        const TextureFootprint f = imageOf(object, view.shadowMatrix);
        if (f.empty)
            continue;
        anywhere = anywhere || f.straddles || !taps.texels;
        // Depth clamp puts casters before the near plane at 0; a margin for the map's rounding.
        const double depth = taps.nearerIsLit ? std::clamp(f.min.z - 1e-4 - offsetDepth, 0.0, 1.0) : kBeforeNear;
        UvRect r{glm::clamp(glm::dvec2(f.min) - taps.grow, 0.0, 1.0) - offsetUv, glm::clamp(glm::dvec2(f.max) + taps.grow, 0.0, 1.0) + offsetUv,
                 depth, hulls ? std::vector<glm::dvec2>(f.points.begin(), f.points.begin() + f.pointCount) : std::vector<glm::dvec2>{}};
        if (r.min.x < r.max.x && r.min.y < r.max.y)
            rects.push_back(r);
    }
    if (anywhere)
        rects.assign(1, UvRect{-offsetUv, 1.0 + offsetUv, taps.nearerIsLit ? 0.0 : kBeforeNear, {}});
    std::vector<ReachBox> boxes;
    const glm::dmat4 textureToWorld = glm::inverse(view.shadowMatrix);
    for (const UvRect& r : mergedRects(std::move(rects))) {
        ReachBox box;
        box.textureToWorld = textureToWorld;
        box.uvMin = r.min;
        box.uvMax = r.max;
        box.depthMin = r.depth;
        box.depthMax = farFace;
        box.uvEdges = hullEdges(r.points, glm::dvec2(taps.grow) + offsetUv);
        for (const glm::dvec3& c : box.worldCorners()) {
            if (!finite(c))
                return std::nullopt;  // a degenerate light matrix: no box to draw
        }
        boxes.push_back(box);
    }
    return boxes;
}

// Where a receiver lies against each view's boxes, in that view's texture space.
Reach receiverReach(const ReachObject& object, const std::vector<LightFrame>& views, const std::vector<std::vector<ReachBox>>& perView)
{
    Reach r = Reach::Outside;
    for (std::size_t v = 0; v < views.size() && r != Reach::Inside; ++v) {
        if (perView[v].empty())
            continue;
        const TextureFootprint f = imageOf(object, views[v].shadowMatrix);
        if (f.empty)
            continue;
        if (f.straddles) {
            r = Reach::Partly;
            continue;
        }
        for (const ReachBox& box : perView[v]) {
            const bool apart = f.max.x < box.uvMin.x || f.min.x > box.uvMax.x || f.max.y < box.uvMin.y || f.min.y > box.uvMax.y
                || f.max.z < box.depthMin || f.min.z > box.depthMax
                || outsideAnEdge(box.uvEdges, glm::dvec2(f.min), glm::dvec2(f.max));
            // What lies outside the map's square or its depth range reads lit whatever the
            // casters, so a receiver is within a box when the rest of it is: its few lookups
            // there cost less than the box's faces in the mask (a caster before the near plane,
            // past the far one or over the map's edge is its own receiver).
            const glm::dvec3 lo = glm::min(glm::dvec3(box.uvMin, box.depthMin), glm::dvec3(0.0));
            const glm::dvec3 hi = glm::max(glm::dvec3(box.uvMax, box.depthMax), glm::dvec3(1.0));
            const glm::dvec3 fMin = glm::clamp(f.min, lo, hi), fMax = glm::clamp(f.max, lo, hi);
            const bool within = fMin.x >= box.uvMin.x && fMax.x <= box.uvMax.x && fMin.y >= box.uvMin.y && fMax.y <= box.uvMax.y
                && fMin.z >= box.depthMin && fMax.z <= box.depthMax;
            if (apart)
                continue;
            if (within)
                return Reach::Inside;
            r = Reach::Partly;
        }
    }
    return r;
}

// The half-spaces of a box, each grown outward by `margin` world units.
std::vector<convex::Plane> boxPlanes(const ReachBox& box, double margin)
{
    // The box as the [-1, 1] cube of a projection from world: its six planes as a frustum's.
    glm::dmat4 toCube(1.0);
    const glm::dvec3 lo(box.uvMin, box.depthMin), hi(box.uvMax, box.depthMax);
    for (int axis = 0; axis < 3; ++axis) {
        toCube[axis][axis] = 2.0 / (hi[axis] - lo[axis]);
        toCube[3][axis] = -1.0 - lo[axis] * toCube[axis][axis];
    }
    const glm::dmat4 worldToTexture = glm::inverse(box.textureToWorld);
    std::vector<convex::Plane> planes;
    for (convex::Plane plane : convex::frustumPlanes(toCube * worldToTexture)) {
        plane.d += margin;
        planes.push_back(plane);
    }
    // An edge's a u + b v + c >= 0 is a x + b y + c w >= 0 of the texture's homogeneous
    // coordinates, in front of the light (w > 0): a plane of world positions through the matrix.
    for (const glm::dvec3& e : box.uvEdges) {
        const glm::dvec4 p = glm::transpose(worldToTexture) * glm::dvec4(e.x, e.y, 0.0, e.z);
        const double length = glm::length(glm::dvec3(p));
        if (length > 0.0 && std::isfinite(length))
            planes.push_back({glm::dvec3(p) / length, p.w / length + margin});
    }
    return planes;
}

// Where a flat receiver's mask must reach past the boxes: its triangles lie on its plane only
// to a millionth of its size (flatPlane) and float rounding moves them as much again, an
// offset the camera sees stretched along the plane by the slant of its view; nothing where it
// sees the plane nearly edge-on, which the boxes' faces then mask instead.
std::optional<double> planeMargin(const ReachObject& receiver, const CameraFrame& camera)
{
    const double size = glm::length(receiver.bounds.max - receiver.bounds.min);
    const double height = std::abs(glm::dot(receiver.plane->normal, camera.position - receiver.plane->point));
    double farthest = 0.0;
    for (const glm::dvec3& c : receiver.bounds.corners())
        farthest = std::max(farthest, glm::length(c - camera.position));
    if (!(height > 1e-3 * farthest))
        return std::nullopt;
    const double offset = 2e-6 * (size + glm::length(receiver.bounds.center()) + glm::length(camera.position));
    return offset * farthest / height;
}

// The part of a flat receiver's plane inside `box`, within its bounds, all grown by `margin`.
convex::Polygon planePiece(const ReachObject& receiver, const ReachBox& box, double margin)
{
    const WorldPlane& plane = *receiver.plane;
    const glm::dvec3 centre = receiver.bounds.center() - plane.normal * glm::dot(plane.normal, receiver.bounds.center() - plane.point);
    const double half = glm::length(receiver.bounds.max - receiver.bounds.min) + margin;
    const glm::dvec3 u = glm::normalize(glm::cross(plane.normal, std::abs(plane.normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(plane.normal, u);
    convex::Polygon piece{centre - half * u - half * v, centre + half * u - half * v, centre + half * u + half * v, centre - half * u + half * v};
    std::vector<convex::Plane> planes = convex::boxHull(receiver.bounds).planes;
    for (convex::Plane& p : planes)
        p.d += margin;
    const std::vector<convex::Plane> inBox = boxPlanes(box, margin);
    planes.insert(planes.end(), inBox.begin(), inBox.end());
    for (const convex::Plane& p : planes) {
        piece = convex::clip(piece, p);
        if (piece.size() < 3)
            return {};
    }
    return piece;
}

// Where a part of the mask lands on screen: the bounding rectangle, in normalised device
// coordinates, of its faces clipped to the camera's frustum; nullopt where none of it is in
// view. A part that reaches behind the camera is cut at the near plane rather than taken as
// the whole screen, so a camera standing on a receiver's piece still gets a mask.
std::optional<std::pair<glm::dvec2, glm::dvec2>> screenBounds(const std::vector<convex::Polygon>& faces, const CameraFrame& camera)
{
    const std::array<convex::Plane, 6> frustum = convex::frustumPlanes(camera.viewProjection);
    const std::vector<convex::Polygon> visible = convex::clipFaces(faces, std::vector<convex::Plane>(frustum.begin(), frustum.end()));
    glm::dvec2 lo(1.0), hi(-1.0);
    bool any = false;
    for (const convex::Polygon& face : visible) {
        for (const glm::dvec3& c : face) {
            const glm::dvec4 clip = camera.viewProjection * glm::dvec4(c, 1.0);
            if (!(clip.w > 0.0))
                continue;       // on the near plane of a degenerate projection: nothing to bound
            lo = glm::min(lo, glm::dvec2(clip) / clip.w);
            hi = glm::max(hi, glm::dvec2(clip) / clip.w);
            any = true;
        }
    }
    if (!any)
        return std::nullopt;
    return std::pair{glm::clamp(lo, -1.0, 1.0), glm::clamp(hi, -1.0, 1.0)};
}

// The mask of the receivers that straddle the boxes: flat ones' pieces, the boxes for the rest.
// Each part's bounding rectangle on screen makes the share and the rectangle.
void buildMask(ShadowReach& reach, const std::vector<ReachObject>& receivers, const CameraFrame& camera)
{
    std::vector<std::vector<convex::Polygon>> parts;    // the faces of each piece or box
    bool boxes = false;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
        if (reach.objects[i] != Reach::Partly)
            continue;
        const std::optional<double> margin = receivers[i].plane ? planeMargin(receivers[i], camera) : std::nullopt;
        if (!margin) {
            boxes = true;
            continue;
        }
        for (const ReachBox& box : reach.boxes) {
            convex::Polygon piece = planePiece(receivers[i], box, *margin);
            if (!piece.empty()) {
                parts.push_back({piece});
                reach.mask.push_back(std::move(piece));
            }
        }
    }
    if (boxes) {
        for (const ReachBox& box : reach.boxes) {
            std::vector<convex::Polygon> faces = box.worldFaces();
            reach.mask.insert(reach.mask.end(), faces.begin(), faces.end());
            parts.push_back(std::move(faces));
        }
    }
    double share = 0.0;
    glm::dvec2 all0(1.0), all1(-1.0);
    std::vector<UvRect> rects;
    for (const std::vector<convex::Polygon>& faces : parts) {
        const std::optional<std::pair<glm::dvec2, glm::dvec2>> bounds = screenBounds(faces, camera);
        if (!bounds)
            continue;
        const auto [lo, hi] = *bounds;
        share += std::max(hi.x - lo.x, 0.0) * std::max(hi.y - lo.y, 0.0) / 4.0;
        all0 = glm::min(all0, lo);
        all1 = glm::max(all1, hi);
        rects.push_back({lo, hi, 0.0, {}});
    }
    reach.screenShare = std::min(share, 1.0);
    reach.screenRect = rects.empty() ? glm::dvec4(0.0) : glm::dvec4(all0, all1);
    for (const UvRect& r : mergedRects(std::move(rects)))
        reach.screenRects.emplace_back(r.min, r.max);
}

} // namespace

bool skippedLookupsReadTheSame(const Settings& settings)
{
    if (!shadowTechnique(settings.filter.mode).litToItsBias)
        return true;
    return settings.filter.momentBias <= kMostBiasShade * std::max(1.0 - settings.filter.bleeding, 0.0);
}

ReachBoxesKey reachBoxesKey(const Settings& settings)
{
    return {skippedLookupsReadTheSame(settings), tapReachTexels(settings), referencesStayNearer(settings), settings.bias.normal};
}

std::optional<ReachBoxes> reachBoxes(const Settings& settings, const std::vector<LightFrame>& views, int mapSize, const std::vector<ReachObject>& casters)
{
    if (!skippedLookupsReadTheSame(settings))
        return std::nullopt;
    TapReach taps;
    taps.texels = tapReachTexels(settings);
    taps.grow = taps.texels ? *taps.texels / double(std::max(mapSize, 1)) : 1.0;
    taps.nearerIsLit = referencesStayNearer(settings);
    ReachBoxes perView;
    for (const LightFrame& view : views) {
        std::optional<std::vector<ReachBox>> boxes = viewBoxes(settings, view, mapSize, casters, taps);
        if (!boxes)
            return std::nullopt;
        perView.push_back(std::move(*boxes));
    }
    return perView;
}

ShadowReach shadowReach(const std::vector<LightFrame>& views, const std::optional<ReachBoxes>& boxes, const std::vector<ReachObject>& objects,
                        const CameraFrame& camera)
{
    if (!boxes)
        return lookupsEverywhere(objects);
    ShadowReach reach;
    for (const std::vector<ReachBox>& view : *boxes)
        reach.boxes.insert(reach.boxes.end(), view.begin(), view.end());
    reach.objects.assign(objects.size(), Reach::Outside);
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (objects[i].receives)
            reach.objects[i] = receiverReach(objects[i], views, *boxes);
    }
    buildMask(reach, objects, camera);
    return reach;
}

ShadowReach shadowReach(const Settings& settings, const std::vector<LightFrame>& views, int mapSize,
                        const std::vector<ReachObject>& casters, const std::vector<ReachObject>& objects, const CameraFrame& camera)
{
    return shadowReach(views, reachBoxes(settings, views, mapSize, casters), objects, camera);
}

} // namespace shadowlab
