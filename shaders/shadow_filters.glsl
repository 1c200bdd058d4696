// The shadow lookup shared by every filter technique, then the technique itself: the lit pass
// defines SHADOW_TECHNIQUE as the file its row of the technique table names (shadow/<key>.glsl),
// which defines float filterShadow(vec2 uv, float reference): 1 lit, 0 shadowed.
// Every compare tap is a hardware depth comparison (sampler2DShadow): the sampler's filter decides
// whether a tap is one texel (nearest) or a bilinear blend of four comparisons (linear).
// Outside the map the border depth of 1.0 makes every tap lit.

uniform sampler2DShadow uShadowMap;
#include LitFrameBlock           // uShadowTexel, the map's texel in uv; uDepthRangeLevel
#ifdef DEPTH_SLICES
#include "depth_slice.glsl"
#endif
// The view a pixel reads (shadow_lookup.glsl), set before it calls filterShadow.
vec2 gShadowUvWorld = vec2(1.0);    // world size of the map's [0, 1] square (perspective: at unit distance)
vec2 gShadowDepthRange = vec2(0.0, 1.0);    // near and far of the view's volume, world units along its axis
vec4 gShadowTile = vec4(0.0, 0.0, 1.0, 1.0);    // its tile, half a texel in: min xy, max xy in map uv

// The receiver, for the wide filters; set by the lit pass before it calls filterShadow.
float gShadowW = 1.0;           // the receiver's clip w (its distance along a perspective light's axis)
float gReferenceDistance = 1.0; // the biased reference's distance along a perspective light's axis (biasedReference)
float gGrowth = 0.0;            // change of depth per world unit of a tap's distance, at the receiver's slope
vec2 gReceiverSlope = vec2(0.0); // depth per uv unit of the receiver's plane (RECEIVER_PLANE)

float shadowTap(vec2 uv, float reference)
{
#ifdef SHADOW_VIEWS
    uv = clamp(uv, gShadowTile.xy, gShadowTile.zw);
#endif
#ifdef DEPTH_SLICES
    // Stored depth; a reference beyond the far plane (a receiver plane's tap may reach there)
    // stays under the gap, lit against what earlier draws left, as a cleared map's clamp to 1.
    reference = min(reference, sliceTop());
#endif
    return texture(uShadowMap, vec3(uv, reference));
}

// World distance from the light (along its axis) of a depth of the map as the depth pass wrote
// it, before any slicing (map.slices): what the min/max depth mip holds.
float depthDistance(float depth)
{
#ifdef REVERSED_Z
    depth = 1.0 - depth;
#endif
    float n = gShadowDepthRange.x, f = gShadowDepthRange.y;
#ifdef LIGHT_PERSPECTIVE
    return n * f / (f - depth * (f - n));
#else
    return n + depth * (f - n);
#endif
}

// World distance from the light (along its axis) of a depth as the map stores it.
float shadowDistance(float depth)
{
#ifdef DEPTH_SLICES
    depth = storedToDepth(depth);
#endif
    return depthDistance(depth);
}

// World length of a tap offset (uv) at the receiver.
float tapWorldLength(vec2 offset)
{
#ifdef LIGHT_PERSPECTIVE
    return length(offset * gShadowUvWorld) * gShadowW;
#else
    return length(offset * gShadowUvWorld);
#endif
}

// The depth a tap `offset` (uv) away from the receiver compares against, for every filter: a
// bias chosen for the centre is wrong for a tap that lies elsewhere on a receiver sloping
// relative to the light, so each tap gets its own. On the receiver's plane with RECEIVER_PLANE
// (exact on planes, wrong where the gradient is: curved receivers, silhouettes); with
// FOOTPRINT_TAPS (the footprint bias where the map holds lit surfaces: no front faces culled)
// the bias grown with the tap's distance by the receiver's slope, the most a planar receiver
// rises toward the light that far away, so no tap of a wide kernel shadows a lit slope (moiré);
// else the centre's (the textbook box filter).
float tapReference(vec2 offset, float reference)
{
#ifdef RECEIVER_PLANE
    return reference + dot(gReceiverSlope, offset);
#elif defined(FOOTPRINT_TAPS)
    return reference + gGrowth * tapWorldLength(offset);
#else
    return reference;
#endif
}

// The comparison of the tap `offset` (uv) away from the receiver at `uv`, against that tap's
// own reference: what every filter sums.
float footprintTap(vec2 uv, vec2 offset, float reference)
{
    return shadowTap(uv + offset, tapReference(offset, reference));
}

// The lowest and highest reference of taps within `radius` (uv, per axis) of the centre.
vec2 tapReferenceRange(vec2 radius, float reference)
{
#ifdef RECEIVER_PLANE
    float spread = dot(abs(gReceiverSlope), radius);
    return vec2(reference - spread, reference + spread);
#elif defined(FOOTPRINT_TAPS)
    float grownBy = gGrowth * tapWorldLength(radius);
    return vec2(min(reference, reference + grownBy), max(reference, reference + grownBy));
#else
    return vec2(reference);
#endif
}

// Interleaved gradient noise (Jimenez 2014): a rotation per pixel that neighbours average out.
mat2 tapRotation()
{
    float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    float c = cos(angle), s = sin(angle);
    return mat2(c, s, -s, c);
}

// 64 points in the unit disk, each placed farthest from those before it, so every prefix of N
// points covers the disk evenly.
const vec2 kPoissonDisk[64] = vec2[64](
    vec2(-0.3525, -0.6987), vec2(0.5682, 0.7945), vec2(0.8406, -0.4862), vec2(-0.7418, 0.5535),
    vec2(0.0261, 0.0852), vec2(-0.9386, -0.2136), vec2(-0.1119, 0.9162), vec2(0.8477, 0.2082),
    vec2(0.3052, -0.8103), vec2(-0.4337, -0.1533), vec2(0.3866, -0.2699), vec2(-0.2675, 0.4437),
    vec2(0.1808, 0.5886), vec2(0.4270, 0.2494), vec2(-0.0807, -0.3846), vec2(-0.7776, 0.1517),
    vec2(-0.7347, -0.6082), vec2(-0.1073, -0.9789), vec2(-0.5028, 0.8327), vec2(0.7375, -0.1538),
    vec2(0.2342, 0.9451), vec2(0.6521, 0.4740), vec2(0.6581, -0.7515), vec2(-0.3495, 0.1345),
    vec2(-0.0086, -0.6964), vec2(-0.4921, -0.4344), vec2(0.4361, -0.5555), vec2(0.1681, 0.3174),
    vec2(0.9760, -0.0269), vec2(0.3114, -0.0025), vec2(-0.5169, 0.3414), vec2(0.1998, -0.4455),
    vec2(-0.1769, -0.0806), vec2(-0.2635, 0.6968), vec2(-0.9282, 0.3636), vec2(0.1211, -0.2073),
    vec2(-0.6891, -0.1472), vec2(0.4225, 0.5868), vec2(0.5720, 0.0463), vec2(-0.5725, -0.7997),
    vec2(0.1467, -0.9677), vec2(-0.4851, 0.5684), vec2(-0.9913, 0.0412), vec2(0.9586, -0.2678),
    vec2(-0.0183, 0.4637), vec2(-0.0247, 0.6913), vec2(-0.7098, -0.3785), vec2(0.8998, 0.4249),
    vec2(0.6038, -0.3881), vec2(-0.3437, -0.9195), vec2(-0.5682, 0.0383), vec2(-0.2812, -0.3328),
    vec2(-0.3141, 0.9076), vec2(-0.1045, 0.2592), vec2(-0.1889, -0.5677), vec2(0.7219, 0.6756),
    vec2(-0.7228, 0.3481), vec2(0.3208, 0.7563), vec2(0.6339, 0.2270), vec2(0.0641, 0.8574),
    vec2(-0.8808, -0.4735), vec2(0.4879, -0.8452), vec2(-0.1827, -0.7825), vec2(0.2483, -0.6364));

#ifdef DEPTH_RANGE
// An atlas of every level (renderer/DepthRangePass.h), read at its level 0: level k holds the
// min (r) and max (g) depth of 2^(k+2) x 2^(k+2) map texels.
uniform sampler2D uDepthRange;

// Level `level`'s texel `p` (clamped to the level), in the atlas's layout.
vec2 rangeTexel(int level, ivec2 p)
{
    ivec4 at = uDepthRangeLevel[level];
    return texelFetch(uDepthRange, at.xy + min(p, at.zw - 1), 0).rg;
}

// The lowest (x) and highest (y) depth of the map texels within `radius` (uv, per axis) of `uv`,
// as the mip's 2 x 2 texels at the level that spans them bound it; the part of the footprint
// outside the map is left out. `bounded` is false where no level spans the footprint.
vec2 footprintRange(vec2 uv, vec2 radius, out bool insideMap, out bool bounded)
{
    vec2 size = floor(1.0 / uShadowTexel + 0.5);    // whole texels: 1 / (1 / 3072) may come out a hair under
    ivec2 lo = ivec2(floor((uv - radius) * size)) - 1;  // a texel of margin for rounding
    ivec2 hi = ivec2(floor((uv + radius) * size)) + 1;
    insideMap = all(greaterThanEqual(lo, ivec2(0))) && all(lessThan(hi, ivec2(size)));
    lo = max(lo, ivec2(0));
    hi = min(hi, ivec2(size) - 1);
    int span = max(hi.x - lo.x, hi.y - lo.y);
    int level = 0;
    while ((4 << level) <= span)
        ++level;                // texels of 2^(level + 2) map texels: the footprint spans at most 2 x 2
    bounded = level < uDepthRangeLevels;
    level = min(level, uDepthRangeLevels - 1);
    ivec2 base = lo >> (level + 2);
    vec2 a = rangeTexel(level, base);
    vec2 b = rangeTexel(level, base + ivec2(1, 0));
    vec2 c = rangeTexel(level, base + ivec2(0, 1));
    vec2 d = rangeTexel(level, base + ivec2(1, 1));
    return vec2(min(min(a.r, b.r), min(c.r, d.r)), max(max(a.g, b.g), max(c.g, d.g)));
}
#endif

#ifdef EARLY_OUT
// Penumbra-only filtering: 1 when every nearest-texel tap within `radius` (uv, per axis) of
// `uv` compares lit against any reference in `references` (lowest, highest), 0 when every one
// compares shadowed, -1 when the footprint may hold a penumbra (or leaves the map: a tap there
// reads the border, which the mip does not hold). Exact: the taps that would be skipped are the
// very comparisons the mip bounds.
float footprintVerdict(vec2 uv, vec2 radius, vec2 references)
{
    bool insideMap, bounded;
    vec2 range = footprintRange(uv, radius, insideMap, bounded);
    if (!insideMap || !bounded)
        return -1.0;
    float nearest = range.x, farthest = range.y;
    // Clamped as the hardware comparison clamps them, and widened a little: the hardware may
    // round the reference to the map's precision before comparing.
#ifdef DEPTH_SLICES
    references = vec2(storedToDepth(references.x), storedToDepth(references.y));
#endif
    references = clamp(references, 0.0, 1.0) + vec2(-1.0e-5, 1.0e-5);
#ifdef REVERSED_Z
    if (references.x > farthest)
        return 1.0;             // every reference nearer the light (greater) than every depth
    if (references.y < nearest)
        return 0.0;
#else
    if (references.y < nearest)
        return 1.0;
    if (references.x > farthest)
        return 0.0;
#endif
    return -1.0;
}
#endif

#include SHADOW_TECHNIQUE
