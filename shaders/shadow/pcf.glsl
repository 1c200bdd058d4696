// pcf: an N x N box of single-texel comparisons (percentage-closer filtering); N is
// PCF_KERNEL (odd), from filter.kernel.
float filterShadow(vec2 uv, float reference)
{
    const int radius = (PCF_KERNEL - 1) / 2;
    float lit = 0.0;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x)
            lit += shadowTap(uv + vec2(x, y) * uShadowTexel, reference);
    }
    return lit / float(PCF_KERNEL * PCF_KERNEL);
}
