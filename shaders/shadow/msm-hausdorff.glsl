// msm-hausdorff: moment shadow maps, 4 moments, Hausdorff reconstruction (Peters and Klein
// 2015; the second variant of MJP's Shadows sample). The same moments as msm, but the depths
// are known to lie in [0, 1]: where the three-depth distribution of the Hamburger solution
// would put a depth outside, a four-depth one inside the interval bounds the shadow instead.
// Sharper where occluders overlap near the ends of the depth range; a few more operations.
#include "msm_common.glsl"

#if !defined(MOMENTS_PASS) && !defined(MOMENTS_VIEW)
float hausdorff(vec4 b, float depth)
{
    vec3 z = momentDepths(b, depth);
    if (z.y >= 0.0 && z.z <= 1.0)
        return threeDepthShadow(b, z);
    // Four depths: the receiver's, 0, 1 and the one the moments leave free.
    float free = safeDivide((b.z - b.y) * depth + b.z - b.w, (b.y - b.x) * depth + b.y - b.z);
    float w1 = depth > free ? 1.0 : 0.0;
    float shadow = safeDivide(b.y - b.x + safeDivide((b.z - b.x - (free + 1.0) * (b.y - b.x)) * (free - w1 - depth),
                                                     depth * (depth - free)),
                              free - w1) + 1.0 - b.x;
    return clamp(shadow, 0.0, 1.0);
}

float filterShadow(vec2 uv, float reference)
{
    if (outsideMap(uv))
        return 1.0;
    return reduceBleeding(1.0 - hausdorff(biasedMoments(uv), momentDepth(reference)));
}
#endif
