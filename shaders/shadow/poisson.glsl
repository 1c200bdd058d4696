// poisson: POISSON_TAPS taps of a Poisson disk of uPoissonRadius texels, rotated per pixel by
// interleaved gradient noise: a round kernel whose sparse taps give fine noise, not bands.
// Each tap's bias grows with its distance (wideTapReference), so a wide disk keeps lit slopes lit.
uniform float uPoissonRadius;   // texels (filter.radius)

float filterShadow(vec2 uv, float reference)
{
    vec2 radius = uPoissonRadius * uShadowTexel;
#ifdef EARLY_OUT
    float verdict = footprintVerdict(uv, radius, tapReferenceRange(radius, reference, true));
    if (verdict >= 0.0)
        return verdict;
#endif
    mat2 rotation = tapRotation();
    float lit = 0.0;
    for (int i = 0; i < POISSON_TAPS; ++i) {
        vec2 offset = rotation * kPoissonDisk[i] * radius;
        lit += shadowTap(uv + offset, wideTapReference(offset, reference));
    }
    return lit / float(POISSON_TAPS);
}
