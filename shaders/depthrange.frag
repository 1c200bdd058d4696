// One level of the shadow map's min/max depth mip (penumbra-only filtering, pcss's and dpcf's
// blocker search): each texel holds the lowest and highest depth of the 2 x 2 texels under it
// one level finer (level 0: of the 4 x 4 map texels under it).
#ifdef FROM_DEPTH
#extension GL_ARB_texture_gather : enable
#endif
// The depth map (FROM_DEPTH) or the level below the one drawn: the atlas, whose origin holds
// level 0, or the mip chain, whose base level the pass sets to that level (texelFetch's level
// counts from the base level).
uniform sampler2D uSource;
uniform ivec2 uSourceSize;  // of the level read (the atlas is wider than its level 0)
#ifdef WRITTEN_ONLY
// What an empty texel holds (1, or 0 in a reversed map): it counts as no depth at all, so
// level 0 and up hold the range of the written texels only (min > max where there are none).
uniform float uEmpty;
#endif

#ifdef FROM_DEPTH
// The map's depth as drawn (map.slices): what earlier draws left reads as the far plane.
#include "depth_slice.glsl"
#endif

out vec2 range;

vec2 fetchRange(ivec2 p)
{
#ifdef FROM_DEPTH
    float depth = sliceDepth(texelFetch(uSource, p, 0).r);
#ifdef WRITTEN_ONLY
    if (depth == uEmpty)
        return vec2(1.0e30, -1.0e30);
#endif
    return vec2(depth);
#else
    return texelFetch(uSource, p, 0).rg;
#endif
}

void main()
{
    ivec2 last = ivec2(uSourceSize - 1);
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
#ifdef FROM_DEPTH
    // Level 0: the 4 x 4 map texels from 4 p (a block past the map's edge reads the border,
    // which only widens its range).
    p *= 2;
#ifdef GL_ARB_texture_gather
    // Four gathers of 2 x 2, each at the corner its four texels share.
    vec2 texel = 1.0 / vec2(uSourceSize);
    vec4 a = sliceDepth(textureGather(uSource, (vec2(p) + vec2(1.0, 1.0)) * texel));
    vec4 b = sliceDepth(textureGather(uSource, (vec2(p) + vec2(3.0, 1.0)) * texel));
    vec4 c = sliceDepth(textureGather(uSource, (vec2(p) + vec2(1.0, 3.0)) * texel));
    vec4 d = sliceDepth(textureGather(uSource, (vec2(p) + vec2(3.0, 3.0)) * texel));
    vec4 lowest = min(min(a, b), min(c, d));
    vec4 highest = max(max(a, b), max(c, d));
#ifdef WRITTEN_ONLY
    // Empty texels out of both: a gathered value is empty only if all four of its sources
    // are, so take each source's range with its empties set aside.
    lowest = min(min(mix(a, vec4(1.0e30), equal(a, vec4(uEmpty))), mix(b, vec4(1.0e30), equal(b, vec4(uEmpty)))),
                 min(mix(c, vec4(1.0e30), equal(c, vec4(uEmpty))), mix(d, vec4(1.0e30), equal(d, vec4(uEmpty)))));
    highest = max(max(mix(a, vec4(-1.0e30), equal(a, vec4(uEmpty))), mix(b, vec4(-1.0e30), equal(b, vec4(uEmpty)))),
                  max(mix(c, vec4(-1.0e30), equal(c, vec4(uEmpty))), mix(d, vec4(-1.0e30), equal(d, vec4(uEmpty)))));
#endif
    range = vec2(min(min(lowest.x, lowest.y), min(lowest.z, lowest.w)), max(max(highest.x, highest.y), max(highest.z, highest.w)));
#else
    range = vec2(1.0e30, -1.0e30);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            vec2 r = fetchRange(min(p + ivec2(x, y), last));
            range = vec2(min(range.x, r.x), max(range.y, r.y));
        }
    }
#endif
#else
    // The next levels follow GL's size rule (each half the one below, rounded down), so where
    // the level below has an odd size the last texel here also takes in the one left over.
    ivec2 end = min(p + 1, last);
    ivec2 lastHere = (last + 1) / 2 - 1;
    if (ivec2(gl_FragCoord.xy).x == lastHere.x)
        end.x = last.x;
    if (ivec2(gl_FragCoord.xy).y == lastHere.y)
        end.y = last.y;
    range = vec2(1.0e30, -1.0e30);
    for (int y = p.y; y <= end.y; ++y) {
        for (int x = p.x; x <= end.x; ++x) {
            vec2 r = fetchRange(ivec2(x, y));
            range = vec2(min(range.x, r.x), max(range.y, r.y));
        }
    }
#endif
}
