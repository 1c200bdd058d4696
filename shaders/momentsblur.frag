// Moments blur: one axis of a separable Gaussian over the moments map, at texel centres (the
// viewport is the map). Moments are linear in the samples, so blurring them is filtering the
// shadow test, which depth-compare maps cannot do. texelFetch, not texture(): no filtering is
// wanted, and a software rasteriser fetches texels far faster than it samples them. The
// radius is a compile-time BLUR_RADIUS so the loop unrolls: with a uniform bound llvmpipe
// took ten times longer.
uniform sampler2D uSource;
uniform ivec2 uStep;            // one texel along this pass's axis
uniform float uWeights[16];     // centre first, summing to 1 over both sides

layout(location = 0) out vec4 fragMoments;

void main()
{
    ivec2 centre = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uSource, 0) - 1;
    vec4 sum = uWeights[0] * texelFetch(uSource, centre, 0);
    for (int i = 1; i <= BLUR_RADIUS; ++i) {
        // Clamped to the edge, as the map's own sampler is.
        sum += uWeights[i] * (texelFetch(uSource, clamp(centre + i * uStep, ivec2(0), last), 0)
                              + texelFetch(uSource, clamp(centre - i * uStep, ivec2(0), last), 0));
    }
    fragMoments = sum;
}
