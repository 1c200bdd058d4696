// Shadow pass: depth only; the rasteriser writes gl_FragCoord.z into the shadow map. A cut-out
// caster leaves its holes out (ALPHA_CUTOUT).
#ifdef ALPHA_CUTOUT
#include "cutout.glsl"
#endif

void main()
{
#ifdef ALPHA_CUTOUT
    if (cutAway())
        discard;
#endif
}
