// vsm: variance shadow maps (Donnelly and Lauritzen 2006). The moments pass stores depth and
// depth squared, and the coverage (moments_common.glsl); filtered, they give the casters' share
// of the footprint, their mean and variance, and Chebyshev's bound how much of them lies behind
// the receiver. One filtered tap; light bleeds where a receiver sees two occluders at different
// depths.
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    return vec4(depth, depth * depth, 1.0, 0.0);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    // Depth and depth squared of the casters, both in [0, 1] (the far plane where none is), and
    // the share they cover.
    if (stored.z < kLeastCoverage)
        return vec4(1.0, 1.0, 0.0, 0.0);
    return vec4(stored.xy / stored.z, stored.z, 0.0);
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    return coveredChebyshev(filteredMoments(uv).rgb, momentDepth(reference), uMomentBias);
}
#endif
