// Shared by the moment techniques (shadow/vsm.glsl, evsm2, evsm4, msm, esm): the depth they
// store, their uniforms, Chebyshev's bound and the light-bleeding reduction. A technique
// defines, in the moments pass (MOMENTS_PASS), vec4 encodeMoments(float depth); in the
// depth-map view (MOMENTS_VIEW), vec4 viewMoments(vec4 stored), each moment as a [0, 1] picture
// (exponential warps undone to depth); in the lit pass, float filterShadow(vec2 uv, float reference).
//
// Coverage (vsm, evsm2, esm: a channel is free after their moments). A caster's fragment stores
// 1 there, and a cleared texel 0 in every channel, so a filtered footprint holds c, the share
// its casters cover, and c times their moments. Divided by c they are the casters' own moments;
// the rest of the footprint saw no caster and is lit. A receiver needs no place in the map, so
// floors are left out and cleared texels are zeros: the blur's identity, and a GPU's fast clear.
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

// The least coverage read as a caster's: below it the footprint is lit, and the division by it
// stays finite (a 16-bit format's smallest normal is 6e-5).
const float kLeastCoverage = 1.0 / 4096.0;

#if !defined(MOMENTS_PASS) && !defined(MOMENTS_VIEW)
uniform sampler2D uShadowMoments;   // filtered: bilinear, trilinear with mips, anisotropic if asked
#include LitFrameBlock               // uBleeding, uMomentBias

// The receiver's depth as the moments pass stores it: linear in [0, 1] between the light
// volume's near and far planes (for a perspective light, distance along its axis: the biased
// reference's own, gReferenceDistance, not one inverted from its depth, which loses the bits an
// exponential warp needs when the near plane is close).
float momentDepth(float reference)
{
    float n = gShadowDepthRange.x, f = gShadowDepthRange.y;
#ifdef LIGHT_PERSPECTIVE
    return clamp((gReferenceDistance - n) / (f - n), 0.0, 1.0);
#elif defined(REVERSED_Z)
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

// The filtered moments at `uv`: one bilinear read of a map blurred by its own pass (or of a
// mip chain, trilinear), or with MOMENTS_LOOKUP_BLUR r the same Gaussian of width 2r + 1 (sigma
// a quarter of it, MomentsBlurPass::weights) applied here to the map as drawn. Bilinear
// filtering after a blur is the blur of the bilinear reads a texel apart; along each axis
// that is 2r + 2 texels, read in pairs by r + 1 bilinear reads whose weights and offsets follow
// the pixel's position between texels: (r + 1)² reads, where the blur pass reads 2 (2r + 1)
// for every texel of the map, looked up or not.
#ifdef MOMENTS_LOOKUP_BLUR
float lookupBlurWeight(int i)
{
    float sigma = float(2 * MOMENTS_LOOKUP_BLUR + 1) / 4.0;
    return abs(i) > MOMENTS_LOOKUP_BLUR ? 0.0 : exp(-0.5 * float(i * i) / (sigma * sigma));
}
#endif

vec4 filteredMoments(vec2 uv)
{
#ifdef MOMENTS_LOOKUP_BLUR
    const int r = MOMENTS_LOOKUP_BLUR;
    vec2 size = vec2(textureSize(uShadowMoments, 0));
    vec2 t = uv * size - 0.5;
    vec2 base = floor(t);
    vec2 f = t - base;      // where the pixel lies between the texels base and base + 1
    float total = lookupBlurWeight(0);
    for (int i = 1; i <= r; ++i)
        total += 2.0 * lookupBlurWeight(i);
    vec2 at[r + 1];
    vec2 weight[r + 1];
    for (int m = 0; m <= r; ++m) {
        // Texels base - r + 2m and the next, each weighted by the blur of the two bilinear weights.
        int j = 2 * m - r;
        vec2 first = lookupBlurWeight(j) * (1.0 - f) + lookupBlurWeight(j - 1) * f;
        vec2 second = lookupBlurWeight(j + 1) * (1.0 - f) + lookupBlurWeight(j) * f;
        weight[m] = (first + second) / total;
        at[m] = (base + float(j) + 0.5 + second / (first + second)) / size;
    }
    vec4 sum = vec4(0.0);
    for (int m = 0; m <= r; ++m) {
        for (int n = 0; n <= r; ++n)
            // Level 0, never a level from derivatives: the taps' pairing shifts between a quad's
            // pixels, which would read as minification.
            sum += weight[m].x * weight[n].y * textureLod(uShadowMoments, momentsUv(vec2(at[m].x, at[n].y)), 0.0);
    }
    return sum;
#else
    return texture(uShadowMoments, momentsUv(uv));
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

// The visibility of a footprint whose casters cover `coverage` of it and let `casterVisibility`
// of that through: the rest is lit.
float coveredVisibility(float coverage, float casterVisibility)
{
    return clamp(1.0 - min(coverage, 1.0) * (1.0 - casterVisibility), 0.0, 1.0);
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

// Chebyshev's bound over the casters of a footprint that stores their coverage c (stored.z) and
// c times their mean and mean square (stored.xy), as the visibility of the whole footprint.
// Scaled by c rather than divided by it, so that an exponential warp's moments near the largest
// float the format holds stay finite: c² σ² = c m2 - m1², c (t - μ) = c t - m1.
float coveredChebyshev(vec3 stored, float depth, float minVariance)
{
    float c = min(stored.z, 1.0);
    if (c < kLeastCoverage || depth * c <= stored.x)
        return 1.0;
    float variance = max(stored.y * c - stored.x * stored.x, minVariance * c * c);
    float d = depth * c - stored.x;
    if (variance <= 0.0)
        return coveredVisibility(c, 0.0);
    return coveredVisibility(c, reduceBleeding(variance / (variance + d * d)));
}
#endif
