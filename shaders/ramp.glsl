// Colour ramps for the debug views, analytic so the shader needs no table.
//
// depthRamp: a perceptual ramp for t in [0, 1] from Green's cubehelix (2011): brightness rises
// linearly (so equal steps in t read as equal steps, and the order survives a grey print) while
// the hue turns from deep blue through green to pale yellow. It stops short of black and white,
// which the depth view keeps for outside the map and for empty texels.
vec3 depthRamp(float t)
{
    float l = mix(0.12, 0.92, clamp(t, 0.0, 1.0));
    float angle = 6.2831853 * (3.0 / 3.0 - 0.7 * l);   // start 3.0, -0.7 rotations
    float amplitude = 1.8 * l * (1.0 - l) / 2.0;
    float c = cos(angle), s = sin(angle);
    return clamp(l + amplitude * vec3(-0.14861 * c + 1.78277 * s, -0.29227 * c - 0.90649 * s, 1.97294 * c), 0.0, 1.0);
}

// densityRamp: the texel density tint, written once for the shader and the window's legend.
#include "shared/density_ramp.glsl"
