// evsm2: exponential variance shadow maps, positive warp only (Lauritzen and McCool 2008).
// Chebyshev's bound on exp(c d) instead of d: the warp pulls a near occluder's share toward 0,
// which shrinks light bleeding; c is limited by what the format holds. The third channel is
// the casters' coverage (moments_common.glsl).
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    float w = warpDepth(depth).x;
    return vec4(w, w * w, 1.0, 0.0);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    if (stored.z < kLeastCoverage)
        return vec4(1.0, 1.0, 0.0, 0.0);
    vec2 casters = stored.xy / stored.z;
    return vec4(unwarpDepth(casters.x, uExponentPositive), unwarpDepth(casters.y, 2.0 * uExponentPositive), stored.z, 0.0);
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    float w = warpDepth(momentDepth(reference)).x;
    // The least variance relative to the warped depth squared: the same share of precision at
    // every depth and exponent.
    return coveredChebyshev(filteredMoments(uv).rgb, w, uMomentBias * w * w);
}
#endif
