// One function per filter technique, chosen by the FILTER_* define the loader injects.
// Every tap is a hardware depth comparison (sampler2DShadow): the sampler's filter decides
// whether a tap is one texel (nearest) or a bilinear blend of four comparisons (linear).
// Outside the map the border depth of 1.0 makes every tap lit.

uniform sampler2DShadow uShadowMap;
uniform vec2 uShadowTexel;      // 1 / map size

float shadowTap(vec2 uv, float reference)
{
    return texture(uShadowMap, vec3(uv, reference));
}

#if defined(FILTER_HARD) || defined(FILTER_HW_BILINEAR)

float filterShadow(vec2 uv, float reference)
{
    return shadowTap(uv, reference);
}

#elif defined(FILTER_PCF)

// N x N box of single-texel comparisons (percentage-closer filtering).
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

#elif defined(FILTER_PCF_DITHER4)

// Four taps of a 4 x 4 footprint whose placement alternates over 2 x 2 pixel blocks
// (GPU Gems 2, ch. 17): 4 lookups, the look of 16 once the eye averages neighbours.
float filterShadow(vec2 uv, float reference)
{
    vec2 offset = vec2(greaterThan(fract(gl_FragCoord.xy * 0.5), vec2(0.25)));
    offset.y += offset.x;
    if (offset.y > 1.1)
        offset.y = 0.0;
    return 0.25 * (shadowTap(uv + (offset + vec2(-1.5, 0.5)) * uShadowTexel, reference)
                 + shadowTap(uv + (offset + vec2(0.5, 0.5)) * uShadowTexel, reference)
                 + shadowTap(uv + (offset + vec2(-1.5, -1.5)) * uShadowTexel, reference)
                 + shadowTap(uv + (offset + vec2(0.5, -1.5)) * uShadowTexel, reference));
}

#elif defined(FILTER_PCF64)

// 8 x 8 taps at half-texel offsets: the smoothest and most expensive box.
float filterShadow(vec2 uv, float reference)
{
    float lit = 0.0;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            lit += shadowTap(uv + (vec2(x, y) - 3.5) * uShadowTexel, reference);
    }
    return lit / 64.0;
}

#else
#error "no FILTER_* define: the loader must inject one"
#endif
