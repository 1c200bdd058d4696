// Depth-map view: the map stretched to the depths its texels actually hold (uSpan) and drawn
// through a perceptual colour ramp, near the light dark, far pale; a perspective light's depth
// is linearised first (raw perspective depth is nearly all one value). Texels nothing was drawn
// into (the far plane) are hatched grey; outside the map is a slate a shade lighter than the pane.
// With LEGEND the pass draws the ramp itself across the viewport, for the colour bar; with
// OVERLAY it draws an image (uDepth holds it, premultiplied, top row first) for blending.
#include "ramp.glsl"
#include "depth_slice.glsl"

in vec2 vUv;

uniform sampler2D uDepth;
uniform float uNear;
uniform float uFar;
uniform vec2 uSpan;     // nearest and farthest written depth (conventional [0, 1] depth)

out vec4 fragColor;

// Conventional depth -> a value that is linear in distance from the light (log for huge far/near).
float linear(float depth)
{
#ifdef LINEARIZE
    float ndc = depth * 2.0 - 1.0;
    float distance = 2.0 * uNear * uFar / (uFar + uNear - ndc * (uFar - uNear));
    return uFar > 1000.0 * uNear ? log(distance / uNear) / log(uFar / uNear) : (distance - uNear) / (uFar - uNear);
#else
    return depth;
#endif
}

void main()
{
#if defined(LEGEND)
    fragColor = vec4(depthRamp(vUv.x), 1.0);
#elif defined(OVERLAY)
    fragColor = texture(uDepth, vec2(vUv.x, 1.0 - vUv.y));
#else
    if (any(lessThan(vUv, vec2(0.0))) || any(greaterThan(vUv, vec2(1.0)))) {
        fragColor = vec4(kOutsideMapColour, 1.0);
        return;
    }
    // What earlier draws of a sliced map (map.slices) left reads as the far plane.
    float depth = sliceDepth(texture(uDepth, vUv).r);
#ifdef REVERSED_Z
    depth = 1.0 - depth;        // reversed maps store 1 - the conventional depth
#endif
    if (depth >= 1.0) {
        float stripe = mod(floor((gl_FragCoord.x + gl_FragCoord.y) / 6.0), 2.0);
        fragColor = vec4(vec3(0.30 + 0.05 * stripe), 1.0);
        return;
    }
    float lo = linear(uSpan.x), hi = linear(uSpan.y);
    float t = hi > lo ? (linear(depth) - lo) / (hi - lo) : 0.5;
    fragColor = vec4(depthRamp(t), 1.0);
#endif
}
