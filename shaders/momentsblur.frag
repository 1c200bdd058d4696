// Moments blur: one axis of a separable Gaussian over the moments map, at texel centres (the
// viewport is the map). Moments are linear in the samples, so blurring them is filtering the
// shadow test, which depth-compare maps cannot do. texelFetch, not texture(): no filtering is
// wanted, and a software rasteriser fetches texels far faster than it samples them. The
// radius is a compile-time BLUR_RADIUS so the loop unrolls: with a uniform bound llvmpipe
// took ten times longer.
uniform sampler2D uSource;
uniform ivec2 uStep;            // one texel along this pass's axis
uniform float uWeights[kMaxBlurWeights];  // centre first, summing to 1 over both sides
uniform ivec2 uTileMin;         // the texels of the tile being blurred (the whole map, or one
uniform ivec2 uTileMax;         // view's tile of several), inclusive: taps stay inside it

layout(location = 0) out vec4 fragMoments;

void main()
{
    ivec2 centre = ivec2(gl_FragCoord.xy);
    vec4 sum = uWeights[0] * texelFetch(uSource, centre, 0);
    for (int i = 1; i <= BLUR_RADIUS; ++i) {
        // Clamped to the tile's edge, as the map's own sampler clamps at the map's.
        sum += uWeights[i] * (texelFetch(uSource, clamp(centre + i * uStep, uTileMin, uTileMax), 0)
                              + texelFetch(uSource, clamp(centre - i * uStep, uTileMin, uTileMax), 0));
    }
    fragMoments = sum;
}
