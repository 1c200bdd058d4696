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

// Where every blocker of a receiver at `receiver` lies: the disk's footprint at the near plane,
// at least a texel, at most half the map.
vec2 blockerSearchRegion(float receiver)
{
    return min(max(diskFootprint(receiver, gShadowDepthRange.x), uShadowTexel), vec2(0.5));
}
