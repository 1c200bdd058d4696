// Depth-map view of a moments map: one stored moment (uChannel) as grey, decoded by the
// technique's own viewMoments() (its row's GLSL file with MOMENTS_VIEW): the first moment is
// the linear depth the technique stored, exponential warps undone. Outside the map: dark blue.
in vec2 vUv;

uniform sampler2D uMoments;
uniform int uChannel;       // 0 to 3

out vec4 fragColor;

#include SHADOW_TECHNIQUE

void main()
{
    if (any(lessThan(vUv, vec2(0.0))) || any(greaterThan(vUv, vec2(1.0)))) {
        fragColor = vec4(kOutsideMapColour, 1.0);
        return;
    }
    vec4 moments = viewMoments(texture(uMoments, vUv));
    fragColor = vec4(vec3(clamp(moments[uChannel], 0.0, 1.0)), 1.0);
}
