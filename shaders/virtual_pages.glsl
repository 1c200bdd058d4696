// Virtual shadow maps (core/VirtualPages.h): which clipmap level and page a receiver needs, the
// same in the request pass and the lit pass's lookup. q0 is the position on level 0's grid in
// pages from that level's window; level l's window-relative position is q0 / 2^l + offset[l].
uniform mat4 uVirtualLight;         // camera-relative world -> (q0, depth as the pages store it)
uniform int uVirtualLevels;
uniform int uVirtualLodBias;        // levels finer than a texel per pixel (shadow.virtual_lod_bias)
uniform vec2 uVirtualLevelOffset[kMaxVirtualLevels];

// The coarsest level whose texel still covers at most one screen pixel: from the change of q0
// across one pixel (dqx, dqy), as an area.
int virtualDensityLevel(vec2 dqx, vec2 dqy)
{
    float texelsPerPixel = float(kVirtualPageTexels) * sqrt(abs(dqx.x * dqy.y - dqx.y * dqy.x));
    int level = (texelsPerPixel > 1.0 ? int(floor(log2(texelsPerPixel))) : 0) - uVirtualLodBias;
    return clamp(level, 0, uVirtualLevels - 1);
}

// Level `level`'s window-relative position of q0, and whether its window holds it.
bool virtualInWindow(int level, vec2 q0, out vec2 q)
{
    q = q0 * exp2(-float(level)) + uVirtualLevelOffset[level];
    return all(greaterThanEqual(q, vec2(0.0))) && all(lessThan(q, vec2(kVirtualLevelPages)));
}

// The level a receiver at q0 asks for: the density's, or the first coarser one whose window
// holds it; -1 for none (outside the coarsest window: beyond the scene).
int virtualRequestLevel(vec2 q0, vec2 dqx, vec2 dqy, out vec2 q)
{
    for (int level = virtualDensityLevel(dqx, dqy); level < uVirtualLevels; ++level) {
        if (virtualInWindow(level, q0, q))
            return level;
    }
    return -1;
}
