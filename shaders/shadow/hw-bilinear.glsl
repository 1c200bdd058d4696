// hw-bilinear: one tap through the linear comparison sampler, which blends the comparisons of
// the four nearest texels: smooth edges for the cost of one lookup.
float filterShadow(vec2 uv, float reference)
{
    return shadowTap(uv, reference);
}
