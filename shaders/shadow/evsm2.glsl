// evsm2: exponential variance shadow maps, positive warp only (Lauritzen and McCool 2008).
// Chebyshev's bound on exp(c d) instead of d: the warp pulls a near occluder's share toward 0,
// which shrinks light bleeding; c is limited by what the format holds.
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    float w = warpDepth(depth).x;
    return vec4(w, w * w, 0.0, 0.0);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    return vec4(unwarpDepth(stored.x, uExponentPositive), unwarpDepth(stored.y, 2.0 * uExponentPositive), 0.0, 0.0);
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    vec2 moments = texture(uShadowMoments, momentsUv(uv)).rg;
    float w = warpDepth(momentDepth(reference)).x;
    // The least variance relative to the warped depth squared: the same share of precision at
    // every depth and exponent.
    return chebyshevUpperBound(moments, w, uMomentBias * w * w);
}
#endif
