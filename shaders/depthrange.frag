// One level of the shadow map's min/max depth mip (penumbra-only filtering): each texel holds
// the lowest and highest depth of the 2 x 2 texels under it one level finer (level 0: of the map
// itself).
// The depth map (FROM_DEPTH) or the level below the one drawn: the atlas, whose origin holds
// level 0, or the mip chain, whose base level the pass sets to that level (texelFetch's level
// counts from the base level).
uniform sampler2D uSource;
uniform int uSourceSize;    // of the level read (the atlas is wider than its level 0)

out vec2 range;

vec2 fetchRange(ivec2 p)
{
#ifdef FROM_DEPTH
    return texelFetch(uSource, p, 0).rr;
#else
    return texelFetch(uSource, p, 0).rg;
#endif
}

void main()
{
    ivec2 last = ivec2(uSourceSize - 1);
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
