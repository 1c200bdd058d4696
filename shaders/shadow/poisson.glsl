// poisson: POISSON_TAPS taps of a Poisson disk of uPoissonRadius texels, rotated per pixel by
// interleaved gradient noise: a round kernel whose sparse taps give fine noise, not bands.
// Each tap's bias grows with its distance (tapReference), so a wide disk keeps lit slopes lit.
#include LitFrameBlock           // uPoissonRadius

float filterShadow(vec2 uv, float reference)
{
    vec2 radius = uPoissonRadius * uShadowTexel;
    int taps = POISSON_TAPS;
    float verdict = -1.0;
#ifdef EARLY_OUT
    verdict = footprintVerdict(uv, radius, tapReferenceRange(radius, reference));
    // A tap count known only per pixel keeps this a loop (see pcf.glsl).
    if (verdict >= 0.0)
        taps = 0;
#endif
    mat2 rotation = tapRotation();
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = rotation * kPoissonDisk[i] * radius;
        lit += footprintTap(uv, offset, reference);
    }
    return verdict >= 0.0 ? verdict : lit / float(POISSON_TAPS);
}
