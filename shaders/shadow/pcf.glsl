// pcf: an N×N box of single-texel comparisons (percentage-closer filtering); N is
// PCF_KERNEL (odd), from filter.kernel.
float filterShadow(vec2 uv, float reference)
{
    const int radius = (PCF_KERNEL - 1) / 2;
    int taps = PCF_KERNEL * PCF_KERNEL;
    float verdict = -1.0;
#ifdef EARLY_OUT
    if (radius > 0) {
        vec2 footprint = float(radius) * uShadowTexel;
        verdict = footprintVerdict(uv, footprint, tapReferenceRange(footprint, reference));
    }
    // A tap count known only per pixel keeps this a loop: a software rasteriser, which runs an
    // unrolled loop for every pixel of a group, leaves it once the group's pixels are decided.
    if (verdict >= 0.0)
        taps = 0;
#endif
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = vec2(i % PCF_KERNEL - radius, i / PCF_KERNEL - radius) * uShadowTexel;
        lit += footprintTap(uv, offset, reference);
    }
    return verdict >= 0.0 ? verdict : lit / float(PCF_KERNEL * PCF_KERNEL);
}
