// pcf: an N x N box of single-texel comparisons (percentage-closer filtering); N is
// PCF_KERNEL (odd), from filter.kernel.
float filterShadow(vec2 uv, float reference)
{
    const int radius = (PCF_KERNEL - 1) / 2;
#ifdef EARLY_OUT
    if (radius > 0) {
        vec2 footprint = float(radius) * uShadowTexel;
        float verdict = footprintVerdict(uv, footprint, tapReferenceRange(footprint, reference, false));
        if (verdict >= 0.0)
            return verdict;
    }
#endif
    float lit = 0.0;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            vec2 offset = vec2(x, y) * uShadowTexel;
            lit += shadowTap(uv + offset, planeTapReference(offset, reference));
        }
    }
    return lit / float(PCF_KERNEL * PCF_KERNEL);
}
