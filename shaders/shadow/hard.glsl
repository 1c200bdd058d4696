// hard: one single-texel comparison; aliased, blocky edges, the cheapest.
float filterShadow(vec2 uv, float reference)
{
    return shadowTap(uv, reference);
}
