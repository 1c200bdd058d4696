#pragma once

#include "Bounds.h"
#include "ConvexClipping.h"
#include "LightMath.h"
#include "Settings.h"

#include <glm/vec2.hpp>

#include <array>
#include <optional>
#include <vector>

namespace shadowlab {

// Where a shadow lookup can find anything but the lit border or the far plane: in each view of
// the light, the casters' footprint on the map, grown by how far the filter's taps reach, over
// the view's whole depth. A receiver outside every such box is lit whatever it reads, so the lit
// pass shades it without a lookup (a variant without one, and a stencil mask of the boxes where
// an object straddles them): the same frame for less work where casters are few.

// How far from the lookup point, in texels of the map, the taps of `settings`' filter read,
// with a margin for rounding; nullopt where the filter may read anywhere in the map (pcss's
// blocker search, a mip or an anisotropic footprint of moments, msm-hausdorff's far plane:
// ShadowTechnique::farPlaneReadsLit). Moments read within the blur's
// radius of their texel: beyond it from any caster they read lit (exactly with coverage; to
// within their bias from a floor's own moments or the far plane's without), which a lookup
// skipped reads exactly.
std::optional<double> tapReachTexels(const Settings& settings);
// How far from the point a pixel shades, in texels of `view`'s map, its lookup may read: the
// taps' reach and the shifts of the normal offset and the footprint bias; nullopt where it may
// read anywhere (as tapReachTexels: pcss's blocker search, mipmapped moments; a normal
// offset off a perspective view, or an offset on a warped one, whose shift has no small bound).
std::optional<double> lookupReachTexels(const Settings& settings, const LightFrame& view);
// How far the normal offset and the footprint bias move a lookup, in texels of the view's wider
// axis (lookupReachTexels scales it to the narrower one).
double lookupShiftTexels(const Settings& settings);
// Whether a receiver no caster reaches, whose lookup the reach skips (shading it lit), reads the
// same looked up. msm reads it lit only to within its moment bias (ShadowTechnique::litToItsBias),
// stretched by the bleeding reduction: its lookups are skipped only while that bias is at most
// kMostBiasShade, where the two differ by less than a step of an 8-bit pixel (the bias's own
// half and the self-shading a sloped receiver's spread of depths leaves under it).
constexpr double kMostBiasShade = 1.0 / 1024.0;
bool skippedLookupsReadTheSame(const Settings& settings);
// Whether every tap of `settings` compares a reference no deeper than the receiver itself, so
// that a receiver nearer the light than every caster is lit: false where the receiver's plane
// or a grown bias moves a tap's reference (wide filters, pcss), for moments, and where a
// negative polygon offset pulls the stored depths nearer than the casters.
bool referencesStayNearer(const Settings& settings);

// One view's reach: a box in that view's shadow-texture space (xy in map uv, z conventional
// depth from its casters' nearest, or 0, or far before the near plane where a tap may compare
// deeper than its receiver, to the far plane; past the map's square and the far plane by what
// the normal offset moves a lookup).
struct ReachBox {
    glm::dvec2 uvMin{0.0}, uvMax{1.0};
    double depthMin = 0.0;
    double depthMax = 1.0;
    glm::dmat4 textureToWorld{1.0};     // inverse of the view's shadowMatrix
    // Half-planes a u + b v + c >= 0 (x, y, z = a, b, c) that cut the rectangle down to the
    // convex hull of its casters' images, grown as the rectangle is: a box turned against the
    // light casts a hexagon, not its bounding rectangle. Empty: the rectangle alone.
    std::vector<glm::dvec3> uvEdges;
    std::array<glm::dvec3, 8> worldCorners() const;
    // The column's faces in world space: the rectangle cut by uvEdges, from depthMin to depthMax.
    std::vector<convex::Polygon> worldFaces() const;
};

enum class Reach { Outside, Partly, Inside };

struct ShadowReach {
    std::vector<ReachBox> boxes;        // empty: nothing can shadow anything
    std::vector<Reach> objects;         // per receiver given (those that receive no shadow: Outside)
    // What the lit pass's stencil mask draws, in world space, for the receivers that straddle
    // the boxes: a flat one's plane inside each box (the pixels of it that need a lookup, and
    // no more), the boxes' faces for any other (every pixel whose ray crosses a box).
    std::vector<convex::Polygon> mask;
    // Share of the viewport the mask may cover (the sum of each piece's or box's bounding
    // rectangle on screen, of what of it lies inside the camera's frustum): a mask that covers
    // most of the frame saves less than drawing the straddling objects twice costs.
    double screenShare = 1.0;
    // The mask's bounding rectangle in normalised device coordinates (min x, min y, max x,
    // max y): the straddling receivers need no lookup outside it. Empty (all 0) where no
    // part is in view.
    glm::dvec4 screenRect{-1.0, -1.0, 1.0, 1.0};
    // The same per part, where parts' rectangles overlap their union: the lookups' draws, one
    // per rectangle, leave out the frame between them.
    std::vector<glm::dvec4> screenRects;
    int generation = 0;                 // set by whoever keeps it: a new value whenever the boxes may have changed
    int outsideCount() const;
    int partlyCount() const;
};

struct WorldPlane {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};   // unit, the side the triangles face
};

struct ReachObject {
    Bounds bounds;                      // world
    // The object's own box through its model (corner i as Bounds::corners()), where known: an
    // object turned against the world's axes covers only the hull of its image on the map.
    std::optional<std::array<glm::dvec3, 8>> box;
    bool casts = false;
    bool receives = false;
    // A flat mesh: the world plane its triangles lie in and face out of. A flat receiver's
    // part of the mask is its plane's pieces inside the boxes.
    std::optional<WorldPlane> plane;
    // A flat one-sided caster whose front faces the shadow pass culls (bias.cull_front): from a
    // light on the side its plane faces nothing of it is drawn.
    bool frontFacesCulled = false;
};

// Whether the light of `view` sees only front faces of the object's culled plane, so that the
// shadow pass draws none of it.
bool culledFrom(const ReachObject& object, const LightFrame& view);

// The reach in two halves, for a caller that keeps the first while only the camera moves:
// each view's boxes of the casters (nullopt: lookups go everywhere), which follow the views, the
// map's size, the casters and the settings' reachBoxesKey; then where the receivers lie against
// them and the mask, which follow the camera.
using ReachBoxes = std::vector<std::vector<ReachBox>>;
struct ReachBoxesKey {
    bool skipsLookups = false;          // skippedLookupsReadTheSame
    std::optional<double> tapTexels;    // tapReachTexels
    bool nearerIsLit = false;           // referencesStayNearer
    double normalOffset = 0.0;          // bias.normal
    bool operator==(const ReachBoxesKey&) const = default;
};
ReachBoxesKey reachBoxesKey(const Settings& settings);
std::optional<ReachBoxes> reachBoxes(const Settings& settings, const std::vector<LightFrame>& views, int mapSize,
                                     const std::vector<ReachObject>& casters);
ShadowReach shadowReach(const std::vector<LightFrame>& views, const std::optional<ReachBoxes>& boxes, const std::vector<ReachObject>& objects,
                        const CameraFrame& camera);

// The reach of a light with the views `views` (one frame per view; their shadowMatrix), over
// maps of `mapSize` texels a side, of the objects in `casters` (those that cast), and where
// each of `receivers` (those that receive) lies against it, seen by `camera`. The two lists
// may differ in granularity: casters one by one for tight columns, receivers as drawn.
ShadowReach shadowReach(const Settings& settings, const std::vector<LightFrame>& views, int mapSize,
                        const std::vector<ReachObject>& casters, const std::vector<ReachObject>& receivers, const CameraFrame& camera);

} // namespace shadowlab
