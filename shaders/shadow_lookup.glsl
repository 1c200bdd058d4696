// The one shadow lookup of the lit pass, for every light: a light has N views in one map (one
// map, the cascades of a directional light, the six faces of a point light), each in its tile.
// A pixel picks its view (the light rig, below: the one view, by view depth, or by the major
// axis of its direction from the light), takes its position in that view, and runs the bias and
// the technique's own filterShadow inside that view's tile.
#include "shared/view_choice.glsl"
uniform float uBiasSlope;           // per unit of (1 - N.L); world units (texels with BIAS_TEXEL, depth units with BIAS_DEPTH)
uniform float uBiasMin;             // the same units
#ifdef FOOTPRINT_BIAS
uniform bool uSelfShadowing;        // false: a floor left out of the map (bias.skip_floors), which needs no bias
#endif
#ifdef OWN_FACETS
uniform bool uOwnFacets;            // a smooth-shaded caster: its facets facing away from the light are in its shadow
#endif
// The views (renderer/UniformBlocks.h declares them), and the frame's bias, cascades and light.
#include ShadowViewBlock
#include LitFrameBlock
// An ortho view is affine (w = 1) and sees one direction to the light, so the bias's step along
// the ray to the light is a constant change of depth per world unit: no division by w and no
// matrix product per pixel.
#if !defined(LIGHT_PERSPECTIVE) && !defined(LIGHT_WARP)
#define AFFINE_VIEW
#endif
// Several views, or a warped one (light.warp = lispsm), take the pixel's position in the map
// here, per pixel; one plain view takes it from the vertex stage.
#if defined(SHADOW_VIEWS) || defined(LIGHT_WARP) || defined(VIRTUAL_MAP)
#define VIEW_PER_PIXEL
#endif

int gViewIndex = -1;                // the view the pixel read (the nearer one of a blend), -1 none
// N.L of the pixel's own facet (a smooth-shaded caster, OWN_FACETS; 1 where unknown), set by
// ownFacetVisibility before the lookup: the map holds the facet, so viewVisibility's bias
// clears the steeper of its slope and the normals'.
float gFacetCosine = 1.0;

#ifdef VIRTUAL_MAP
#include "virtual_pages.glsl"
uniform usampler2D uVirtualPageTable;   // per level a window's rows of pages: slot + 1 of the page there, 0 none
#endif

// What the lookup needs of a view: its matrix (camera-relative world to map uv and depth), its
// tile in map uv, the world size of the whole map's uv square at its scale, its depth range and
// the world size of its texel.
struct ShadowViewLookup {
    mat4 matrix;
    vec4 tile;
    vec2 uvWorld;
    vec2 depth;
    float texel;
    float rayDepth;             // AFFINE_VIEW: depth change per world unit toward the light
};

ShadowViewLookup shadowView(int i)
{
#ifdef AFFINE_VIEW
    float rayDepth = uShadowViewTexelRay[i].y;
#else
    float rayDepth = 0.0;
#endif
    return ShadowViewLookup(uShadowViewMatrix[i], uShadowViewTile[i], uShadowViewUvWorldDepth[i].xy, uShadowViewUvWorldDepth[i].zw,
                            uShadowViewTexelRay[i].x, rayDepth);
}

#ifdef LIGHT_WARP
// A warped map's texels differ in size over the map: the world size of the whole map's uv
// square at the map position `c` of view i, per axis of the map, from how uv changes across
// the light's rays (which stay parallel under the warp, each one texel).
vec2 warpUvWorld(mat4 view, vec4 c, vec3 toLight)
{
    if (c.w <= 0.0)
        return vec2(0.0);       // behind the warp's centre: outside the map, lit
    vec3 a = normalize(cross(toLight, abs(toLight.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(toLight, a);
    vec4 ca = view * vec4(a, 0.0), cb = view * vec4(b, 0.0);
    vec2 uv = c.xy / c.w;
    vec2 ja = (ca.xy - uv * ca.w) / c.w, jb = (cb.xy - uv * cb.w) / c.w;   // uv per world unit along a and b
    float det = ja.x * jb.y - jb.x * ja.y;
    return vec2(length(vec2(jb.y, ja.y)), length(vec2(jb.x, ja.x))) / max(abs(det), 1e-30);
}

// The world size of a texel there, the wider axis.
float warpTexel(vec2 uvWorld)
{
    return max(uvWorld.x * uShadowTexel.x, uvWorld.y * uShadowTexel.y);
}
#endif

// The footprint's move along the normal, in texels (viewPosition), and its clearance along the
// ray, in texels of depth (biasedReference): 0 without FOOTPRINT_BIAS or on a floor left out.
float footprintNormalTexels(float cosTheta, float sinTheta)
{
#ifdef FOOTPRINT_BIAS
    return uSelfShadowing ? 0.5 * max(sinTheta - cosTheta, 0.0) : 0.0;
#else
    return 0.0;
#endif
}

float footprintRayTexels(float tanTheta)
{
#ifdef FOOTPRINT_BIAS
    return uSelfShadowing ? 0.5 * min(tanTheta, 1.0) : 0.0;
#else
    return 0.0;
#endif
}

// The lookup's steps, one helper per axis, so that viewVisibility reads as their sequence: where
// the view sees the pixel and its scales there (ortho, perspective, warped), the bias in its
// space, the comparison in the map's depth convention.

// The world size of the whole map's uv square where the view sees `position`: a warped map's
// texels differ in size over the map.
vec2 viewUvWorld(ShadowViewLookup view, vec4 position, vec3 toLight)
{
#ifdef LIGHT_WARP
    return warpUvWorld(view.matrix, position, toLight);
#else
    return view.uvWorld;
#endif
}

// The world size of a texel where the map's uv square spans uvWorld.
float viewTexel(ShadowViewLookup view, vec2 uvWorld)
{
#ifdef LIGHT_WARP
    return warpTexel(uvWorld);
#else
    return view.texel;
#endif
}

// `texels` of `texel` world size, in world units at a receiver of clip w: a perspective texel
// grows with the distance from the light.
float texelsToWorld(float texels, float texel, float w)
{
#ifdef LIGHT_PERSPECTIVE
    return texels * texel * w;
#else
    return texels * texel;
#endif
}

#ifdef VIEW_PER_PIXEL
// Several views' position is taken here, as each pixel picks its own view: moved along the
// normal by bias.normal and the footprint's `texels`.
vec4 pixelPosition(ShadowViewLookup view, vec3 normal, vec3 toLight, float texels)
{
    vec4 plain = view.matrix * vec4(vPosition, 1.0);
    float offset = texelsToWorld(uNormalOffsetTexels + texels, viewTexel(view, viewUvWorld(view, plain, toLight)), plain.w);
    return plain + view.matrix * vec4(normal * offset, 0.0);
}
#endif

// One view's position comes from the vertex stage (vShadowCoord, in the exact object-space path,
// interpolated) with bias.normal's offset, and the normal's step in the map for the footprint's
// `offset` (world units) from there too: no matrix product per pixel (a branch around one cost
// llvmpipe more).
vec4 vertexPosition(float offset)
{
#if !defined(FOOTPRINT_BIAS)
    return vShadowCoord;
#elif defined(LIGHT_PERSPECTIVE)
    return vShadowCoord + vShadowNormal * offset;
#else
    return vShadowCoord + vec4(vShadowNormal * offset, 0.0);    // an ortho view's w stays 1
#endif
}

// The light rig: where view i sees the pixel, moved off the surface by the normal offset.
vec4 viewPosition(ShadowViewLookup view, vec3 normal, vec3 toLight, float cosTheta, float sinTheta)
{
    // The lookup's own footprint (FOOTPRINT_BIAS): the texel it reads lies up to half a texel
    // across the map from the receiver, where a receiver sloping by theta to the light lies up
    // to half a texel times tan(theta) nearer the light. Up to 45 degrees that clearance is taken
    // along the ray to the light (footprintRayTexels), which moves nothing across the map; beyond,
    // where tan(theta) grows without bound, the rest is a move along the normal of half a texel
    // times (sin - cos)(theta), whose distance to the plane along the ray is that over
    // cos(theta): bounded by half a texel however grazing the light, and small where the light
    // is high, so shadow edges on lit ground do not shift. Measured against a normal offset
    // alone (edges of cut-out shadows moved) and a ray offset alone (terminator acne on real
    // models) in docs/techniques.md#bias.
    float footprint = footprintNormalTexels(cosTheta, sinTheta);
#ifdef VIEW_PER_PIXEL
    return pixelPosition(view, normal, toLight, footprint);
#else
    return vertexPosition(texelsToWorld(footprint, view.texel, vShadowCoord.w));
#endif
}

// Whether `position` lies behind a perspective light, outside its volume; an ortho view's w is 1.
bool behindLight(vec4 position)
{
#ifdef AFFINE_VIEW
    return false;
#else
    return position.w <= 0.0;
#endif
}

// The map uv and depth of `position`: no division by an ortho view's w of 1.
vec3 mapCoord(vec4 position)
{
#ifdef AFFINE_VIEW
    return position.xyz;
#else
    return position.xyz / position.w;
#endif
}

// Whether a map depth lies beyond the far plane, which is lit.
bool beyondFarPlane(float depth)
{
#ifdef REVERSED_Z
    return depth < 0.0;         // depth 0 when reversed
#elif defined(DEPTH_SLICES)
    return depth > sliceTop();  // stored (depth_slice.glsl)
#else
    return depth > 1.0;
#endif
}

// A screen-space step of the pixel (rigVisibility's dx or dy) in this view's map coordinates:
// through the view's matrix with several views, as derivatives of the coordinate itself are
// undefined where neighbours pick other views; one view's steps are taken in the map already.
vec3 mapStep(ShadowViewLookup view, vec3 d)
{
#ifdef VIEW_PER_PIXEL
    vec4 c0 = view.matrix * vec4(vPosition, 1.0);
    vec4 c = view.matrix * vec4(vPosition + d, 1.0);
    return c.xyz / c.w - c0.xyz / c0.w;
#else
    return d;
#endif
}

// The receiver's depth as a plane over the map (RECEIVER_PLANE), as depth change per uv unit,
// from the pixel's screen-space change in map coordinates. A degenerate footprint (the plane
// seen edge-on from the camera) gets a flat plane, as every receiver does without.
vec2 receiverSlope(ShadowViewLookup view, vec3 dx, vec3 dy)
{
#ifdef RECEIVER_PLANE
    vec3 ddx = mapStep(view, dx), ddy = mapStep(view, dy);
    float det = ddx.x * ddy.y - ddx.y * ddy.x;
    return abs(det) > 1e-20 ? vec2(ddx.z * ddy.y - ddx.y * ddy.z, ddx.x * ddy.z - ddx.z * ddy.x) / det : vec2(0.0);
#else
    return vec2(0.0);
#endif
}

// The change of map depth per world unit toward the light at `position`: an ortho view's is a
// constant of the view.
float depthPerWorldAt(ShadowViewLookup view, vec4 position, vec3 toLight)
{
#ifdef AFFINE_VIEW
    return view.rayDepth;
#else
    vec4 alongRay = view.matrix * vec4(toLight, 0.0);
    return (alongRay.z * position.w - position.z * alongRay.w) / (position.w * position.w);
#endif
}

// Near and far of the view's volume in world units along its axis. Along a ray a warped depth
// is linear in distance, at a scale of this texel's own: the depth range here, from 0, in world
// units (as an ortho view's, for shadowDistance).
vec2 viewDepthRange(ShadowViewLookup view, float depthPerWorld)
{
#ifdef LIGHT_WARP
    return vec2(0.0, 1.0 / max(abs(depthPerWorld), 1e-30));
#else
    return view.depth;
#endif
}

// A view at the receiver: where it sees it (viewPosition), that position's map uv and depth, the
// world size of a texel there and the change of depth per world unit toward the light.
struct ViewPoint {
    vec4 position;
    vec3 coord;
    float texel;
    float depthPerWorld;
};

// The map depth of the receiver moved `units` world units toward the light: on the ray to the
// light, so it stays on the same texel, and the same offset whatever the depth range. A
// perspective view's distance of that point along its axis, its w, goes to gReferenceDistance.
float depthTowardLight(ShadowViewLookup view, ViewPoint p, vec3 toLight, float units)
{
#ifdef AFFINE_VIEW
    return p.coord.z + units * p.depthPerWorld;
#else
    vec4 moved = p.position + view.matrix * vec4(toLight * units, 0.0);
    gReferenceDistance = moved.w;
    return moved.z / moved.w;
#endif
}

// A map depth moved `bias` depth units toward the light: nearer the light is greater reversed.
float nearerLight(float depth, float bias)
{
#ifdef REVERSED_Z
    return depth + bias;
#else
    return depth - bias;
#endif
}

// The bias in world units: as set (bias.space=world), or its texels' world size (texel).
float worldBias(float bias, ViewPoint p, float tanTheta)
{
#if defined(BIAS_TEXEL)
    return texelsToWorld(bias, p.texel, p.position.w);
#elif defined(VIRTUAL_MAP)
    // A virtual level's texel is about a screen pixel wherever it lies, so its size spans the
    // levels and no one world-unit bias fits them all: at least the depth this receiver's own
    // plane spans over one texel of its level, the reach of a lookup's 2 x 2 comparison
    // footprint along the slope, or it shadows itself (acne; half a texel's diagonal, a hard
    // lookup's reach, still left the default hw-bilinear's partial acne on a model's ground).
    return max(bias, p.texel * tanTheta);
#else
    return bias;
#endif
}

// A perspective view's distance along its axis of the map depth `shift` depth units from the
// receiver's. Taken from 1 / w, which is affine in the map's depth, and the receiver's exact w,
// never by inverting the shifted depth: near 1 a float's depth holds too few bits for that when
// the near plane is close (a point light inside a model's bounds fits its near plane at 1e-4 of
// the far one, and a distance inverted from depth is then off by 1e-4 of itself, which an
// exponential warp's moments read as shadow).
float distanceOfShift(ViewPoint p, float shift)
{
#ifdef REVERSED_Z
    shift = -shift;
#endif
    float n = gShadowDepthRange.x, f = gShadowDepthRange.y;
    return 1.0 / (1.0 / p.position.w - shift * (f - n) / (n * f));
}

// The depth the filter compares against: the receiver's, moved toward the light by the bias in
// bias.space's units and by the footprint's clearance along the ray. A perspective view's
// distance of it goes to gReferenceDistance for the techniques that store distance (moments).
float biasedReference(ShadowViewLookup view, ViewPoint p, float cosTheta, vec3 toLight, float tanTheta)
{
    // (1 - N.L) <= 1: bounded at grazing angles, where slope * tan(theta) would explode.
    float bias = max(uBiasSlope * (1.0 - cosTheta), uBiasMin);
    float footprint = texelsToWorld(footprintRayTexels(tanTheta), p.texel, p.position.w);
#ifdef BIAS_DEPTH
#ifdef LIGHT_PERSPECTIVE
    gReferenceDistance = distanceOfShift(p, nearerLight(0.0, bias) + footprint * p.depthPerWorld);
#endif
    return nearerLight(p.coord.z, bias) + footprint * p.depthPerWorld;
#else
    return depthTowardLight(view, p, toLight, worldBias(bias, p, tanTheta) + footprint);
#endif
}

// How much nearer the light, along the ray, a receiver's plane at theta to the ray lies per
// world unit of a tap's distance across the map, at most. tan(theta) where the map's depth runs
// along the ray (an ortho view). A perspective light's depth runs along its view's axis, so off
// the axis by phi a plane facing the light squarely still rises toward it across the map: by
// sin(alpha) / cos(theta) for alpha the normal's angle to the axis, at most
// sin(min(theta + phi, 90 degrees)) / cos(theta) (sin(phi) alone, 0.82, at a cube face's
// corner). A warped map's depth (light.warp=lispsm) runs along its warp's axis, across the
// light, and is not bounded here.
// Capped at 3 (72 degrees): beyond it the lookup's normal offset holds the centre, and a larger
// growth lit grazing receivers in a crest's own shadow; on real models 3 misclassifies least
// (docs/techniques.md#bias). A blocker search (pcss, dpcf) caps it at 10 (84 degrees): its taps
// reach across the whole region a disk light's blockers may lie in, where a grazing receiver's
// own surface rose above a growth of 3 and read as blockers (dpcf on anim_test: 0.29 %
// misclassified against the area light, 0.02 % at 10).
#ifdef BLOCKER_SEARCH
const float kGrowthCap = 10.0;
#else
const float kGrowthCap = 3.0;
#endif
float growthSlope(ShadowViewLookup view, vec3 toLight, float cosTheta, float sinTheta)
{
    float c = max(cosTheta, 1e-6);
#ifdef LIGHT_PERSPECTIVE
    // The row of the view's matrix that gives w: its axis.
    vec3 axis = vec3(view.matrix[0][3], view.matrix[1][3], view.matrix[2][3]);
    float cosPhi = clamp(-dot(toLight, axis) * inversesqrt(max(dot(axis, axis), 1e-30)), 0.0, 1.0);
    float sinPhi = sqrt(1.0 - cosPhi * cosPhi);
    // sin(theta + phi), or 1 past a right angle (where cos(theta + phi) < 0).
    float sinMost = cosTheta * cosPhi < sinTheta * sinPhi ? 1.0 : sinTheta * cosPhi + cosTheta * sinPhi;
    return min(sinMost / c, kGrowthCap);
#else
    return min(sinTheta / c, kGrowthCap);
#endif
}

// A view's visibility of the pixel; dx, dy are its screen-space steps (rigVisibility): in
// camera-relative world with several views, in the map coordinate looked up with one.
float viewVisibility(ShadowViewLookup view, vec3 normal, vec3 toLight, vec3 dx, vec3 dy)
{
    // The receiver's angle to the light, once, the steeper of its normal's and its facet's:
    // rounding can put N.L above 1, so no NaN.
    float cosTheta = clamp(min(dot(normal, toLight), gFacetCosine), 0.0, 1.0);
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    ViewPoint p;
    p.position = viewPosition(view, normal, toLight, cosTheta, sinTheta);
    if (behindLight(p.position))
        return 1.0;             // behind a perspective light: outside its volume
    p.coord = mapCoord(p.position);
    if (beyondFarPlane(p.coord.z))
        return 1.0;             // beyond the far plane is lit
    if (dot(normal, toLight) <= 0.0)
        return 0.0;             // facing away from the light: unlit anyway
    vec4 tile = view.tile;
    if (any(lessThan(p.coord.xy, tile.xy)) || any(greaterThan(p.coord.xy, tile.zw)))
        return 1.0;             // outside the view's fitted volume every tap would read lit
    // Taps stay inside the tile (half a texel in), so a wide filter never reads a neighbour.
    gShadowTile = vec4(tile.xy + 0.5 * uShadowTexel, tile.zw - 0.5 * uShadowTexel);
    gShadowUvWorld = viewUvWorld(view, p.position, toLight);
    gReceiverSlope = receiverSlope(view, dx, dy);
    p.texel = viewTexel(view, gShadowUvWorld);
    p.depthPerWorld = depthPerWorldAt(view, p.position, toLight);
    gShadowDepthRange = viewDepthRange(view, p.depthPerWorld);
    // For the wide filters: a tap d world units away on this receiver's plane lies up to
    // d growthSlope nearer the light (d tan(theta) for an ortho view); gGrowth is that in depth
    // per world unit.
    float tanTheta = min(sinTheta / max(cosTheta, 1e-6), 3.0);
    gGrowth = p.depthPerWorld * growthSlope(view, toLight, cosTheta, sinTheta);
    gShadowW = p.position.w;
    return filterShadow(p.coord.xy, biasedReference(view, p, cosTheta, toLight, tanTheta));
}

#ifdef VIRTUAL_MAP
// The page table's entry for level `level` at its window-relative position q: slot + 1, or 0.
uint virtualPageEntry(int level, vec2 q)
{
    ivec2 at = (clamp(ivec2(floor(q)), ivec2(0), ivec2(kVirtualLevelPages - 1)) + uVirtualWrap[level].xy) % kVirtualLevelPages;
    return texelFetch(uVirtualPageTable, ivec2(at.x, at.y + level * kVirtualLevelPages), 0).r;
}

// A virtual map's lookup: the level the pixel asked for (virtual_pages.glsl), else the one
// finer (the request pass's rounding of the same derivatives) or the nearest coarser level
// with the page resident; then that page's slot of the pool as an ortho view of its own.
float virtualVisibility(vec3 normal, vec3 toLight, vec3 dx, vec3 dy)
{
    vec2 q0 = (uVirtualLight * vec4(vPosition, 1.0)).xy;
    vec2 dqx = (uVirtualLight * vec4(dx, 0.0)).xy, dqy = (uVirtualLight * vec4(dy, 0.0)).xy;
    vec2 q;
    int asked = virtualRequestLevel(q0, dqx, dqy, q);
    if (asked < 0)
        return 1.0;             // beyond the coarsest window: beyond the scene, lit
    int level = -1;
    uint entry = 0u;
    for (int k = -1; k < uVirtualLevels && entry == 0u; ++k) {
        int l = virtualFallbackLevel(asked, k);
        if (l < 0 || l >= uVirtualLevels || !virtualInWindow(l, q0, q))
            continue;
        entry = virtualPageEntry(l, q);
        level = l;
    }
    gViewIndex = level;
    if (entry == 0u)
        return 1.0;             // no page resident at any level (cannot happen once requested)
    int slot = int(entry) - 1;
    vec2 slotOrigin = vec2(slot % uVirtualPoolSide, slot / uVirtualPoolSide) * float(kVirtualSlotTexels);
    // q0 -> the slot's texels: level scale, the page's place in the window, its border.
    float scale = exp2(-float(level));
    vec2 page = floor(q);
    vec2 atlas = 1.0 / uShadowTexel;
    mat4 toSlot = mat4(1.0);
    toSlot[0][0] = float(kVirtualPageTexels) * scale / atlas.x;
    toSlot[1][1] = float(kVirtualPageTexels) * scale / atlas.y;
    toSlot[3].xy = (slotOrigin + float(kVirtualPageBorder) + float(kVirtualPageTexels) * (uVirtualLevelOffset[level].xy - page)) / atlas;
    float texel = uVirtualTexel0 * exp2(float(level));
    // The slot's matrix leaves depth as the light's: its step toward the light is the light's.
    ShadowViewLookup view = ShadowViewLookup(toSlot * uVirtualLight, vec4(slotOrigin / atlas, (slotOrigin + float(kVirtualSlotTexels)) / atlas),
                                             atlas * texel, uShadowViewUvWorldDepth[0].zw, texel, (uVirtualLight * vec4(toLight, 0.0)).z);
    return viewVisibility(view, normal, toLight, dx, dy);
}
#endif

// The light rig's choice of view, then that view's visibility.
float rigVisibility(vec3 normal, vec3 toLight)
{
    // Screen-space steps, taken here where every pixel of a quad still runs: of the position
    // with several views, of the very coordinate looked up with one.
#ifdef VIEW_PER_PIXEL
    vec3 dx = dFdx(vPosition), dy = dFdy(vPosition);
#else
    vec3 mapCoord = vShadowCoord.xyz / vShadowCoord.w;
    vec3 dx = dFdx(mapCoord), dy = dFdy(mapCoord);
#endif
#if defined(LIGHT_POINT)
    int face = cubeFace(vPosition - uLightPosition);
    gViewIndex = face;
    return viewVisibility(shadowView(face), normal, toLight, dx, dy);
#elif defined(CASCADES)
    float depth = dot(vPosition - uViewOrigin, uViewForward);
    int i = cascadeIndex(depth, uCascadeFar, uShadowViewCount);
    if (i < 0)
        return 1.0;             // beyond shadow.distance
    gViewIndex = i;
    float v = viewVisibility(shadowView(i), normal, toLight, dx, dy);
    if (i + 1 < uShadowViewCount && depth > uCascadeBlendStart[i]) {
        float t = (depth - uCascadeBlendStart[i]) / max(uCascadeFar[i] - uCascadeBlendStart[i], 1e-30);
        v = mix(v, viewVisibility(shadowView(i + 1), normal, toLight, dx, dy), t);
    }
    return v;
#elif defined(VIRTUAL_MAP)
    return virtualVisibility(normal, toLight, dx, dy);
#else
    gViewIndex = 0;
    return viewVisibility(shadowView(0), normal, toLight, dx, dy);
#endif
}

// 0 where the pixel's own facet faces away from the light, else 1. A smooth-shaded mesh is
// faceted: near its terminator a facet can face away from the light while the normals it is
// shaded with still face it. The light cannot reach such a facet: the facet's own neighbours
// stand between, a fraction of a facet away, which no map resolves and which every bias
// clears, so a filter reads it lit or partly lit (the moment filters most: light leaks along a
// low-poly model's terminator). The facet is the plane of the pixel's own triangle, from the
// screen-space steps of its position (each taken on its own triangle), turned to the side its
// normals shade; a triangle seen edge-on, whose steps span no plane, counts as facing, and so
// does a facet along the light's rays to within kOwnFacetCosine (as the reference's). It also
// leaves the facet's N.L in gFacetCosine for the lookup's bias, so it runs before rigVisibility.
float ownFacetVisibility(vec3 normal, vec3 toLight)
{
#ifdef OWN_FACETS
    vec3 facet = cross(dFdx(vPosition), dFdy(vPosition));
    float side = sign(dot(facet, normal));
    float towardLight = dot(facet, toLight) * side;
    float size = length(facet);
    if (uOwnFacets && size > 0.0 && side != 0.0)
        gFacetCosine = towardLight / size;
    return uOwnFacets && towardLight < -kOwnFacetCosine * size ? 0.0 : 1.0;
#else
    return 1.0;
#endif
}

// The shadow term of the pixel: its own facet's, then the light rig's lookup (in that order: the
// lookup's bias reads the facet's slope).
float shadowVisibility(vec3 normal, vec3 toLight)
{
    // Both take screen-space steps, so both run on every pixel of a quad.
    float own = ownFacetVisibility(normal, toLight);
    return own * rigVisibility(normal, toLight);
}

// The overlay colour of a view: cascades red, green, blue, yellow; faces add magenta and cyan.
vec3 viewTint(int i)
{
    const vec3 tints[] = kViewTints;
    return i < 0 ? vec3(1.0) : tints[i % tints.length()];   // virtual maps' levels go round them
}
