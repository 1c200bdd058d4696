// Camera depth prepass for contact shadows: the distance along the view, into the red channel
// for the nearest front faces and the green one for the nearest back faces (the colour mask
// picks the channel of each pass), so the march reads both in one lookup. A cut-out caster
// leaves its holes out (ALPHA_CUTOUT).
in float vViewDepth;

layout(location = 0) out vec2 viewDepth;
#ifdef ALPHA_CUTOUT
#include "cutout.glsl"
#endif

void main()
{
#ifdef ALPHA_CUTOUT
    if (cutAway())
        discard;
#endif
    viewDepth = vec2(vViewDepth);
}
