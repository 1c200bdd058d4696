// Moments blur: one axis of a separable Gaussian over the moments map, at texel centres (the
// viewport is the map). Moments are linear in the samples, so blurring them is filtering the
// shadow test, which depth-compare maps cannot do.
in vec2 vUv;

uniform sampler2D uSource;      // nearest, clamped to the edge
uniform vec2 uStep;             // one texel along this pass's axis
uniform int uRadius;            // taps each side of the centre
uniform float uWeights[16];     // centre first, summing to 1 over both sides

layout(location = 0) out vec4 fragMoments;

void main()
{
    vec4 sum = uWeights[0] * texture(uSource, vUv);
    for (int i = 1; i <= uRadius; ++i)
        sum += uWeights[i] * (texture(uSource, vUv + float(i) * uStep) + texture(uSource, vUv - float(i) * uStep));
    fragMoments = sum;
}
