// esm: exponential shadow maps (Annen et al. 2008). The moments pass stores exp(c d); filtered,
// it times exp(-c t) approximates the share of the footprint in front of the receiver at t.
// One moment and the casters' coverage (moments_common.glsl), one tap; no bleeding between
// occluders, but light leaks where receiver and occluder are closer than about 1/c of the depth
// range (contacts).
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    return vec4(exp(uExponentPositive * depth), 1.0, 0.0, 0.0);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    if (stored.y < kLeastCoverage)
        return vec4(1.0, 0.0, 0.0, 0.0);
    float casters = stored.x / stored.y;
    float depth = uExponentPositive > 0.0 ? clamp(log(max(casters, 1e-30)) / uExponentPositive, 0.0, 1.0) : 0.0;
    return vec4(depth, stored.y, 0.0, 0.0);
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    vec2 stored = filteredMoments(uv).rg;
    float coverage = min(stored.y, 1.0);
    if (coverage < kLeastCoverage)
        return 1.0;
    // exp(c (d - t)) <= 1 in front; the product stays finite as c <= ln(largest float), and
    // is compared with the coverage before dividing by it.
    float casters = min(stored.x * exp(-uExponentPositive * momentDepth(reference)), coverage) / coverage;
    return coveredVisibility(coverage, casters);
}
#endif
