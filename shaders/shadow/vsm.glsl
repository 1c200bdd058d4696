// vsm: variance shadow maps (Donnelly and Lauritzen 2006). The moments pass stores depth and
// depth squared; filtered, they give the footprint's mean and variance, and Chebyshev's bound
// how much of it lies behind the receiver. One filtered tap; light bleeds where a receiver
// sees two occluders at different depths.
#include "moments_common.glsl"

#ifdef MOMENTS_PASS
vec4 encodeMoments(float depth)
{
    return vec4(depth, depth * depth, 0.0, 0.0);
}
#elif defined(MOMENTS_VIEW)
vec4 viewMoments(vec4 stored)
{
    return stored;              // depth and depth squared, both in [0, 1]
}
#else
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    vec2 moments = texture(uShadowMoments, momentsUv(uv)).rg;
    return chebyshevUpperBound(moments, momentDepth(reference), uMomentBias);
}
#endif
