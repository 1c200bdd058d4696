// Shared by the moment techniques (shadow/vsm.glsl, evsm2, evsm4, msm, esm): the depth they
// store, their uniforms, Chebyshev's bound and the light-bleeding reduction. A technique
// defines, in the moments pass (MOMENTS_PASS), vec4 encodeMoments(float depth); in the
// depth-map view (MOMENTS_VIEW), vec4 viewMoments(vec4 stored), each moment as a [0, 1] picture
// (exponential warps undone to depth); in the lit pass, float filterShadow(vec2 uv, float reference).
uniform float uExponentPositive;    // esm, evsm: the warp exp(c d), already clamped to what the format holds
uniform float uExponentNegative;    // evsm4: the warp -exp(-c d)

// EVSM warps depth mapped to [-1, 1], so both warps use the whole exponent range.
vec2 warpDepth(float depth)
{
    float d = 2.0 * depth - 1.0;
    return vec2(exp(uExponentPositive * d), -exp(-uExponentNegative * d));
}

// The depth in [0, 1] whose warp exp(exponent (2 depth - 1)) is `warped` (up to sign): for the view.
float unwarpDepth(float warped, float exponent)
{
    if (exponent == 0.0)
        return 0.5;
    return clamp(0.5 * log(max(abs(warped), 1e-30)) / exponent + 0.5, 0.0, 1.0);
}

#if !defined(MOMENTS_PASS) && !defined(MOMENTS_VIEW)
uniform sampler2D uShadowMoments;   // filtered: bilinear, trilinear with mips, anisotropic if asked
#include LitFrameBlock               // uBleeding, uMomentBias

// The receiver's depth as the moments pass stores it: linear in [0, 1] between the light
// volume's near and far planes (for a perspective light, distance along its axis).
float momentDepth(float reference)
{
#if defined(LIGHT_PERSPECTIVE) || defined(REVERSED_Z)
    float n = gShadowDepthRange.x, f = gShadowDepthRange.y;
    return clamp((shadowDistance(reference) - n) / (f - n), 0.0, 1.0);
#else
    return clamp(reference, 0.0, 1.0);  // an ortho light's depth is already linear
#endif
}

// Where a technique samples the moments: with several views, inside the pixel's view's tile
// (half a texel in), so bilinear filtering never blends a neighbouring view in.
vec2 momentsUv(vec2 uv)
{
#ifdef SHADOW_VIEWS
    return clamp(uv, gShadowTile.xy, gShadowTile.zw);
#else
    return uv;
#endif
}

// Outside the map nothing was rendered: lit, as the depth-compare techniques' border says.
bool outsideMap(vec2 uv)
{
    return any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)));
}

// Light-bleeding reduction: the tail of the bound below uBleeding becomes full shadow.
float reduceBleeding(float visibility)
{
    return clamp((visibility - uBleeding) / (1.0 - uBleeding), 0.0, 1.0);
}

// Chebyshev's one-sided upper bound on the share of the filtered footprint not in front of
// `depth`, from its mean and mean square (Donnelly and Lauritzen 2006). Finite for any input
// the clamped formats can hold: the variance is at least minVariance, and a zero variance
// returns before dividing.
float chebyshevUpperBound(vec2 moments, float depth, float minVariance)
{
    if (depth <= moments.x)
        return 1.0;
    float variance = max(moments.y - moments.x * moments.x, minVariance);
    float d = depth - moments.x;
    if (variance <= 0.0)
        return 0.0;
    return reduceBleeding(variance / (variance + d * d));
}
#endif
