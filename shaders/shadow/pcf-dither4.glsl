// Four taps of a 4×4 footprint whose placement alternates over 2×2 pixel blocks
// (GPU Gems 2, ch. 17): 4 lookups, the look of 16 once the eye averages neighbours.
float filterShadow(vec2 uv, float reference)
{
    vec2 offset = vec2(greaterThan(fract(gl_FragCoord.xy * 0.5), vec2(0.25)));
    offset.y += offset.x;
    if (offset.y > 1.1)
        offset.y = 0.0;
    return 0.25 * (footprintTap(uv, (offset + vec2(-1.5, 0.5)) * uShadowTexel, reference)
                 + footprintTap(uv, (offset + vec2(0.5, 0.5)) * uShadowTexel, reference)
                 + footprintTap(uv, (offset + vec2(-1.5, -1.5)) * uShadowTexel, reference)
                 + footprintTap(uv, (offset + vec2(0.5, -1.5)) * uShadowTexel, reference));
}
