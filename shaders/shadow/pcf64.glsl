// 8 x 8 taps at half-texel offsets: the smoothest and most expensive box.
float filterShadow(vec2 uv, float reference)
{
    float lit = 0.0;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            lit += footprintTap(uv, (vec2(x, y) - 3.5) * uShadowTexel, reference);
    }
    return lit / 64.0;
}
