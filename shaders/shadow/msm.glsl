// msm: moment shadow maps, 4 moments, Hamburger reconstruction (Peters and Klein 2015). The
// moments pass stores depth to the fourth power; the lit pass finds the distribution of three
// depths that matches the filtered moments and has the most mass behind the receiver, a
// sharper bound than Chebyshev's. 16-bit maps store the moments through the authors'
// optimised quantisation, a linear map that spreads them over the format's precision.
#include "msm_common.glsl"

#if !defined(MOMENTS_PASS) && !defined(MOMENTS_VIEW)
float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    vec4 b = biasedMoments(uv);
    return reduceBleeding(1.0 - threeDepthShadow(b, momentDepths(b, momentDepth(reference))));
}
#endif
