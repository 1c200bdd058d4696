// Depth-map view: raw depth for an ortho light, linear distance between near and far for a
// perspective one (raw perspective depth is nearly all white). Outside the map: dark blue.
in vec2 vUv;

uniform sampler2D uDepth;
uniform float uNear;
uniform float uFar;

out vec4 fragColor;

void main()
{
    if (any(lessThan(vUv, vec2(0.0))) || any(greaterThan(vUv, vec2(1.0)))) {
        fragColor = vec4(0.08, 0.09, 0.13, 1.0);
        return;
    }
    float depth = texture(uDepth, vUv).r;
#ifdef REVERSED_Z
    depth = 1.0 - depth;        // reversed maps store 1 - the conventional depth
#endif
#ifdef LINEARIZE
    float ndc = depth * 2.0 - 1.0;
    float distance = 2.0 * uNear * uFar / (uFar + uNear - ndc * (uFar - uNear));
    // A huge far/near ratio puts everything near black on a linear scale: go logarithmic.
    depth = uFar > 1000.0 * uNear ? log(distance / uNear) / log(uFar / uNear) : (distance - uNear) / (uFar - uNear);
#endif
    fragColor = vec4(vec3(depth), 1.0);
}
