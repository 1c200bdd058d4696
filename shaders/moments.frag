// Moments pass: the technique's encoding of the fragment's depth (its row's GLSL file, with
// MOMENTS_PASS). Casters before the near plane are clamped to it, as in the depth pass, and a
// cut-out caster leaves its holes out (ALPHA_CUTOUT).
#ifdef LIGHT_PERSPECTIVE
in float vDepth;
#else
in vec2 vClipDepth;
#endif

layout(location = 0) out vec4 fragMoments;

#include SHADOW_TECHNIQUE
#ifdef ALPHA_CUTOUT
#include "cutout.glsl"
#endif

void main()
{
#ifdef ALPHA_CUTOUT
    if (cutAway())
        discard;
#endif
#ifdef LIGHT_PERSPECTIVE
    float depth = vDepth;
#else
    float depth = vClipDepth.x / vClipDepth.y * 0.5 + 0.5;
#endif
    fragMoments = encodeMoments(clamp(depth, 0.0, 1.0));
}
