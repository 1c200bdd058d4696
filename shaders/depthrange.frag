// One level of the shadow map's min/max depth mip (penumbra-only filtering): each texel holds
// the lowest and highest depth of the 2 x 2 texels under it one level finer (level 0: of the map
// itself).
// The depth map (FROM_DEPTH) or the range texture, whose base level the pass sets to the level
// below the one drawn: texelFetch's level counts from the base level.
uniform sampler2D uSource;
#ifdef WRITTEN_ONLY
// What an empty texel holds (1, or 0 in a reversed map): it counts as no depth at all, so
// level 0 and up hold the range of the written texels only (min > max where there are none).
uniform float uEmpty;
#endif

out vec2 range;

vec2 fetchRange(ivec2 p)
{
#ifdef FROM_DEPTH
    float depth = texelFetch(uSource, p, 0).r;
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
    ivec2 last = textureSize(uSource, 0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
#ifdef FROM_DEPTH
    // Level 0 halves the map rounding up: each texel covers its own 2 x 2 (clamped at the edge).
    vec2 a = fetchRange(min(p, last));
    vec2 b = fetchRange(min(p + ivec2(1, 0), last));
    vec2 c = fetchRange(min(p + ivec2(0, 1), last));
    vec2 d = fetchRange(min(p + ivec2(1, 1), last));
    range = vec2(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)));
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
