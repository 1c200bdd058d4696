// evsm4: exponential variance shadow maps with both warps, exp(c+ d) and -exp(-c- d), and
// the smaller of their two bounds: the negative warp removes the bleeding the positive one
// leaves near the receiver. Four moments, twice evsm2's memory and bandwidth.
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    vec2 w = warpDepth(depth);
    return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    return vec4(unwarpDepth(stored.x, uExponentPositive), unwarpDepth(stored.y, 2.0 * uExponentPositive),
                unwarpDepth(stored.z, -uExponentNegative), unwarpDepth(stored.w, -2.0 * uExponentNegative));
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    vec4 moments = filteredMoments(uv);
    vec2 w = warpDepth(momentDepth(reference));
    vec2 minVariance = uMomentBias * w * w;  // relative to the warped depth squared, as in evsm2
    float positive = chebyshevUpperBound(moments.xy, w.x, minVariance.x);
    float negative = chebyshevUpperBound(moments.zw, w.y, minVariance.y);
    return min(positive, negative);
}
#endif
