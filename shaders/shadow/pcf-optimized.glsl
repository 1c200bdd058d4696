// pcf-optimized: the wide PCF of The Witness (Castaño 2013; MJP's Shadows sample, OptimizedPCF):
// a smooth PCF_KERNEL×PCF_KERNEL kernel (3, 5 or 7 texels) from ((N + 1) / 2)² bilinear
// compare taps. Each tap sits where the hardware's blend of its four texels gives each of them
// the kernel's weight, so 4, 9 or 16 lookups filter what pcf's box does in 9, 25 or 49, with
// weights that fall off toward the kernel's edge: a smoother penumbra, no staircase.
const int kAxisTaps = (PCF_KERNEL + 1) / 2;

// Along one axis, for a receiver `s` (in [0, 1)) of a texel past the base texel's centre: each
// tap's position in texels from that centre, and its weight.
void axisTaps(float s, out float at[kAxisTaps], out float weight[kAxisTaps])
{
#if PCF_KERNEL == 3
    weight[0] = 3.0 - 2.0 * s;
    weight[1] = 1.0 + 2.0 * s;
    at[0] = (2.0 - s) / weight[0] - 1.0;
    at[1] = s / weight[1] + 1.0;
#elif PCF_KERNEL == 5
    weight[0] = 4.0 - 3.0 * s;
    weight[1] = 7.0;
    weight[2] = 1.0 + 3.0 * s;
    at[0] = (3.0 - 2.0 * s) / weight[0] - 2.0;
    at[1] = (3.0 + s) / weight[1];
    at[2] = s / weight[2] + 2.0;
#else
    // The 7-wide kernel's weights come out negative along both axes; their products are not.
    weight[0] = 5.0 * s - 6.0;
    weight[1] = 11.0 * s - 28.0;
    weight[2] = -(11.0 * s + 17.0);
    weight[3] = -(5.0 * s + 1.0);
    at[0] = (4.0 * s - 5.0) / weight[0] - 3.0;
    at[1] = (4.0 * s - 16.0) / weight[1] - 1.0;
    at[2] = -(7.0 * s + 5.0) / weight[2] + 1.0;
    at[3] = -s / weight[3] + 3.0;
#endif
}

float filterShadow(vec2 uv, float reference)
{
#ifdef EARLY_OUT
    // The taps blend texels up to half a kernel and one texel from the receiver.
    vec2 footprint = (float(PCF_KERNEL - 1) * 0.5 + 1.0) * uShadowTexel;
    float verdict = footprintVerdict(uv, footprint, tapReferenceRange(footprint, reference));
    if (verdict >= 0.0)
        return verdict;
#endif
    vec2 texel = uv / uShadowTexel;             // map texels, texel i spanning [i, i + 1]
    vec2 nearestCorner = floor(texel + 0.5);
    vec2 s = texel + 0.5 - nearestCorner;
    vec2 base = nearestCorner - 0.5;            // the centre of the texel just before that corner
    float atU[kAxisTaps], weightU[kAxisTaps], atV[kAxisTaps], weightV[kAxisTaps];
    axisTaps(s.x, atU, weightU);
    axisTaps(s.y, atV, weightV);
    float lit = 0.0, total = 0.0;
    for (int j = 0; j < kAxisTaps; ++j) {
        for (int i = 0; i < kAxisTaps; ++i) {
            vec2 tap = (base + vec2(atU[i], atV[j])) * uShadowTexel;
            float weight = weightU[i] * weightV[j];
            lit += weight * footprintTap(uv, tap - uv, reference);
            total += weight;
        }
    }
    // Summed in another order than `total`, a fully lit footprint may round an ulp above 1.
    return min(lit / total, 1.0);
}
