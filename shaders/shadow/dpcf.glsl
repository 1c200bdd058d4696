// dpcf: PCF with contact hardening (Myers, Shadows of Cold War; Filament's DPCF). One pass of
// POISSON_TAPS taps over pcss's blocker search region both finds the blockers and filters:
// no second pass at the penumbra's width, as pcss makes. Where the blockers lie near the
// receiver, the penumbra a planar blocker there casts is narrower than the region. Filament's
// form sharpens the fraction occluded over the whole region by as much; over a region much
// wider than a small caster's shadow that fraction stays under one half and the shadow reads
// lit. Here the pass also counts the taps within half and three quarters of the region's
// radius, so the fraction is taken over the taps within the penumbra (at least half the
// radius: a quarter of the taps), then steepened by as much as that is still too wide.
#include "blocker_search.glsl"

float filterShadow(vec2 uv, float reference)
{
    float receiver = shadowDistance(reference);
    vec2 search = blockerSearchRegion(uv, receiver);
#ifdef EARLY_OUT
    // Every tap lies in the search region: all lit there is no blocker, all shadowed is 0.
    float verdict = footprintVerdict(uv, search, tapReferenceRange(search, reference));
    if (verdict >= 0.0)
        return verdict;
#endif
    // Blockers as pcss finds them, each tap against its own reference (tapReference: a lit slope
    // holds none), and counted as occluded within half and three quarters of the region's radius
    // and in all. Counted against the centre's reference instead, a receiver's own slope occluded
    // its taps on the side toward the light wherever any blocker was found: acne along curved
    // models' terminators and over a ground drawn into the map (torus, bias.cull_front=false:
    // 13.8 % of the pixels misclassified against the area reference, 1.2 % now; docs/techniques.md
    // has the models' figures).
    mat2 rotation = tapRotation();
    float blockerSum = 0.0, blockers = 0.0;
    vec3 occluded = vec3(0.0), taps = vec3(0.0);
    for (int i = 0; i < POISSON_TAPS; ++i) {
        float distance = length(kPoissonDisk[i]);
        vec3 within = vec3(step(distance, 0.5), step(distance, 0.75), 1.0);
        vec2 offset = rotation * kPoissonDisk[i] * search;
        float depth = blockerDepth(uv + offset);
        taps += within;
        if (isBlocker(depth, tapReference(offset, reference))) {
            blockerSum += depth;
            blockers += 1.0;
            occluded += within;
        }
    }
    if (blockers == 0.0)
        return 1.0;
    float blocker = shadowDistance(blockerSum / blockers);
    // The penumbra's radius over the region's (at least a texel, so contacts stay anti-aliased),
    // and the radius the fraction is taken over.
    float penumbra = clamp(length(max(diskFootprint(receiver, blocker), uShadowTexel)) / length(search), 0.0, 1.0);
    float radius = max(penumbra, 0.5);
    // The fraction occluded within that radius, between those of the rings around it.
    vec3 fractions = occluded / max(taps, vec3(1.0));
    float fraction = radius < 0.75 ? mix(fractions.x, fractions.y, (radius - 0.5) * 4.0) : mix(fractions.y, fractions.z, (radius - 0.75) * 4.0);
    // Across a straight edge the fraction occluded under a disk of radius r rises with slope
    // 4 / (pi r) at its middle: steepened by radius / penumbra about one half, it rises as a
    // disk of the penumbra's radius would.
    return 1.0 - clamp(0.5 + (fraction - 0.5) * (radius / penumbra), 0.0, 1.0);
}
