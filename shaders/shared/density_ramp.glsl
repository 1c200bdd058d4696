// The texel density tint (shading.texel_density): screen pixels per shadow texel on a log
// scale, blue under 1 (the map is finer than the screen), green 1 to 2, yellow about 4, red
// from 8 up (blocky edges). The lit pass tints with it and the window's legend draws it.
vec3 densityRamp(float pixelsPerTexel)
{
    float k = clamp(log2(max(pixelsPerTexel, 1e-6f)) / 3.0f, -1.0f, 1.0f);   // -1: 1/8, 0: 1, 1: 8 pixels
    if (k < 0.0f)
        return mix(kDensityGreen, kDensityBlue, clamp(-k * 3.0f, 0.0f, 1.0f));
    if (k < 0.5f)
        return mix(kDensityGreen, kDensityYellow, (k - 0.1f) / 0.4f * step(0.1f, k));
    return mix(kDensityYellow, kDensityRed, (k - 0.5f) * 2.0f);
}
