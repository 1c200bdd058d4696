// A depth map drawn into slices (map.slices, renderer/ShadowMap.h): its last draw wrote depth d
// at uShadowSlice.x + d * uShadowSlice.y. A gap lies above that, then the slices earlier draws
// left, which from uShadowSlice.z up read beyond the far plane, as a cleared texel does.
// (0, 1, 1): a map cleared every draw.
uniform vec3 uShadowSlice;

#include "shared/depth_slice_decode.glsl"

// A stored value as conventional depth; at most 1.
float sliceDepth(float stored)
{
    return sliceDepthOf(stored, uShadowSlice);
}

vec4 sliceDepth(vec4 stored)
{
    return vec4(sliceDepth(stored.x), sliceDepth(stored.y), sliceDepth(stored.z), sliceDepth(stored.w));
}

// The lit pass's lookups compare in stored depth: their shadow matrix folds the slice in
// (DepthSlice::matrix), so a tap pays nothing for it. The far plane, stored:
float sliceTop()
{
    return uShadowSlice.x + uShadowSlice.y;
}

// A stored value as a lookup reads it: what earlier draws left (from uShadowSlice.z up) reads
// as the far plane, as a cleared texel does.
float sliceStored(float stored)
{
    return stored >= uShadowSlice.z ? sliceTop() : stored;
}

// A stored reference as conventional depth (for distances and the min/max mip, which are kept
// in conventional depth).
float storedToDepth(float stored)
{
    return (stored - uShadowSlice.x) / uShadowSlice.y;
}
