// Virtual shadow maps (core/VirtualPages.h): which clipmap level and page a receiver needs. The
// request pass asks with these, the lit pass's lookup reads with them, and the texel density
// measure (lab/TexelDensity) follows them. q0 is the receiver's position on level 0's grid, in
// pages; level l's window-relative position is q0 / 2^l + that level's offset.

// The coarsest level whose texel still covers at most one screen pixel, where a pixel spans
// `texelsPerPixel` level-0 texels (the side of its area), made `lodBias` levels finer
// (shadow.virtual_lod_bias) and kept within the `levels` there are.
int virtualDensityLevel(float texelsPerPixel, int lodBias, int levels)
{
    int level = (texelsPerPixel > 1.0f ? int(floor(log2(texelsPerPixel))) : 0) - lodBias;
    return clamp(level, 0, levels - 1);
}

// The level a lookup tries k-th, from k = -1: the level asked for, then the one finer (the
// request pass's rounding of the same derivatives), then each coarser one. It may lie outside
// the levels there are.
int virtualFallbackLevel(int asked, int k)
{
    return k < 0 ? asked : (k == 0 ? asked - 1 : asked + k);
}

// Level `level`'s window-relative position of q0, where its window lies at `offset`.
vec2 virtualLevelPosition(int level, vec2 q0, vec2 offset)
{
    return q0 * exp2(-float(level)) + offset;
}

// Whether a level's window holds the window-relative position q.
bool virtualWindowHolds(vec2 q)
{
    return all(greaterThanEqual(q, vec2(0.0f))) && all(lessThan(q, vec2(float(kVirtualLevelPages))));
}

// A request for `page` (window-relative) of `level`, as the request pass writes it: 1 + level
// * n² + y * n + x for a window of n² pages (n = kVirtualLevelPages); 0 is no request.
uint virtualPackRequest(int level, ivec2 page)
{
    return 1u + uint(level * kVirtualLevelPages * kVirtualLevelPages + page.y * kVirtualLevelPages + page.x);
}

// A request's level and window-relative page (x, y); `value` must not be 0.
ivec3 virtualUnpackRequest(uint value)
{
    uint n = uint(kVirtualLevelPages);
    uint v = value - 1u;
    return ivec3(int(v / (n * n)), int(v % n), int((v / n) % n));
}
