// Virtual shadow maps (core/VirtualPages.h): which clipmap level and page a receiver needs, the
// same in the request pass and the lit pass's lookup. q0 is the position on level 0's grid in
// pages from that level's window; level l's window-relative position is q0 / 2^l + offset[l].
#include VirtualMapBlock

#include "shared/virtual_levels.glsl"

// The level whose texel covers about one screen pixel, from the change of q0 across one pixel
// (dqx, dqy), as an area.
int virtualPixelLevel(vec2 dqx, vec2 dqy)
{
    float texelsPerPixel = float(kVirtualPageTexels) * sqrt(abs(dqx.x * dqy.y - dqx.y * dqy.x));
    return virtualDensityLevel(texelsPerPixel, uVirtualLodBias, uVirtualLevels);
}

// Level `level`'s window-relative position of q0, and whether its window holds it.
bool virtualInWindow(int level, vec2 q0, out vec2 q)
{
    q = virtualLevelPosition(level, q0, uVirtualLevelOffset[level].xy);
    return virtualWindowHolds(q);
}

// The level a receiver at q0 asks for: the density's, or the first coarser one whose window
// holds it; -1 for none (outside the coarsest window: beyond the scene).
int virtualRequestLevel(vec2 q0, vec2 dqx, vec2 dqy, out vec2 q)
{
    for (int level = virtualPixelLevel(dqx, dqy); level < uVirtualLevels; ++level) {
        if (virtualInWindow(level, q0, q))
            return level;
    }
    return -1;
}
