// pcss: percentage-closer soft shadows (Fernando 2005) of a disk light. A blocker search over
// the part of the map the light's disk covers as seen from the receiver, the blockers' mean
// distance, then a Poisson filter as wide as the penumbra a planar blocker there would cast:
// (receiver - blocker) times the disk's angular radius for a directional light, as the area
// reference traces it, and by similar triangles for a perspective one.
#include "blocker_search.glsl"

float filterShadow(vec2 uv, float reference)
{
    float receiver = shadowDistance(reference);
    // Every blocker lies between the near plane and the receiver, so the penumbra filter below
    // stays inside this search region.
    vec2 search = blockerSearchRegion(uv, receiver);
#ifdef EARLY_OUT
    // Every tap of both loops lies in the search region: where it is all lit there is no blocker
    // (1), where it is all shadowed every filter tap is too (0).
    float verdict = footprintVerdict(uv, search, tapReferenceRange(search, reference));
    if (verdict >= 0.0)
        return verdict;
#endif
    mat2 rotation = tapRotation();
    float blockerSum = 0.0;
    float blockers = 0.0;
    for (int i = 0; i < kPcssBlockerTaps; ++i) {
        vec2 offset = rotation * kPoissonDisk[i] * search;
        float depth = blockerDepth(uv + offset);
        if (isBlocker(depth, tapReference(offset, reference))) {
            blockerSum += depth;
            blockers += 1.0;
        }
    }
    if (blockers == 0.0)
        return 1.0;
    float blocker = shadowDistance(blockerSum / blockers);
    // At least one texel, so contact shadows stay anti-aliased.
    vec2 radius = clamp(diskFootprint(receiver, blocker), uShadowTexel, search);
    float lit = 0.0;
    for (int i = 0; i < POISSON_TAPS; ++i) {
        vec2 offset = rotation * kPoissonDisk[i] * radius;
        lit += footprintTap(uv, offset, reference);
    }
    return lit / float(POISSON_TAPS);
}
