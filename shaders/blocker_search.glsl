// Shared by the techniques that search the map for blockers between a disk light and the
// receiver (shadow/pcss.glsl, shadow/dpcf.glsl): the raw depths, the light's size, and where
// the light's disk lies on the map as seen from the receiver.
uniform sampler2D uShadowDepth; // the same map, raw depth
#include LitFrameBlock           // uLightSize

bool isBlocker(float depth, float reference)
{
#ifdef REVERSED_Z
    return depth > reference;
#else
    return depth < reference;
#endif
}

// The raw depth at `at`, kept inside the view's own tile as shadowTap keeps a compare tap.
float blockerDepth(vec2 at)
{
#ifdef SHADOW_VIEWS
    at = clamp(at, gShadowTile.xy, gShadowTile.zw);
#endif
#ifdef DEPTH_SLICES
    return sliceStored(texture(uShadowDepth, at).r);   // what earlier draws left: no blocker
#else
    return texture(uShadowDepth, at).r;
#endif
}

// The uv radius covered by the light's disk, seen from a receiver at `receiver`, at distance
// `plane` from the light (both along its axis).
vec2 diskFootprint(float receiver, float plane)
{
#ifdef LIGHT_PERSPECTIVE
    return vec2(uLightSize * (receiver - plane) / (receiver * plane)) / gShadowUvWorld;
#else
    return vec2(uLightSize * (receiver - plane)) / gShadowUvWorld;
#endif
}

// Where every blocker of the receiver at `uv`, `receiver` from the light, lies: the disk's
// footprint at the nearest depth a blocker may have, at least a texel, at most half the map.
// That depth is first the near plane's. Then, twice, the nearest the map holds under the region
// (the min/max depth mip, DEPTH_RANGE): no blocker in it is nearer, and one outside it shadows
// nothing here, so the region for that depth still holds every blocker. The near plane alone
// spans half the map when it lies close to the light, as a fit puts it for a point light inside
// a model's bounds, and 16 taps over half the map found blockers far from the receiver's own
// (a rock under a point light: pcss 4.8 % of the pixels misclassified, dpcf 15 %).
vec2 blockerSearchRegion(vec2 uv, float receiver)
{
    vec2 region = min(max(diskFootprint(receiver, gShadowDepthRange.x), uShadowTexel), vec2(0.5));
    // Not under a warp (light.warp): its depth converts to distance at the receiver's own scale,
    // which does not bound another texel's.
#if defined(DEPTH_RANGE) && !defined(LIGHT_WARP)
    for (int i = 0; i < 2; ++i) {
        // Only the part inside the view's tile: taps are clamped into it, so what lies beyond
        // holds none of them (and a point light's 3 x 2 faces would take the whole map's level).
        vec2 lo = max(uv - region, gShadowTile.xy), hi = min(uv + region, gShadowTile.zw);
        bool insideMap, bounded;
        vec2 range = footprintRange(0.5 * (lo + hi), 0.5 * max(hi - lo, vec2(0.0)), insideMap, bounded);
        if (!bounded)
            break;
        // A hair nearer the light, for the depth's rounding near 1.
#ifdef REVERSED_Z
        float nearest = range.y + 1e-5;     // nearer the light is greater
#else
        float nearest = range.x - 1e-5;
#endif
        float plane = max(depthDistance(nearest), gShadowDepthRange.x);
        region = min(max(diskFootprint(receiver, plane), uShadowTexel), region);
    }
#endif
    return region;
}
