// 8×8 (kPcf64Side²) taps at half-texel offsets: the smoothest and most expensive box.
float filterShadow(vec2 uv, float reference)
{
    float lit = 0.0;
    for (int y = 0; y < kPcf64Side; ++y) {
        for (int x = 0; x < kPcf64Side; ++x)
            lit += footprintTap(uv, (vec2(x, y) - kPcf64TapReach) * uShadowTexel, reference);
    }
    return lit / float(kPcf64Side * kPcf64Side);
}
