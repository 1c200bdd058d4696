// A depth map drawn into slices (map.slices, renderer/ShadowMap.h): its last draw wrote depth d
// at uShadowSlice.x + d * uShadowSlice.y. A gap lies above that, then the slices earlier draws
// left, which from uShadowSlice.z up read beyond the far plane, as a cleared texel does.
// (0, 1, 1): a map cleared every draw.
uniform vec3 uShadowSlice;

// A stored value as conventional depth; at most 1.
float sliceDepth(float stored)
{
    return stored >= uShadowSlice.z ? 1.0 : min((stored - uShadowSlice.x) / uShadowSlice.y, 1.0);
}

vec4 sliceDepth(vec4 stored)
{
    return vec4(sliceDepth(stored.x), sliceDepth(stored.y), sliceDepth(stored.z), sliceDepth(stored.w));
}

// A comparison's reference as stored, clamped to [0, 1] as a 24-bit map clamps it: beyond the
// far plane it stays under the gap, lit against what earlier draws left.
float sliceReference(float reference)
{
    return uShadowSlice.x + clamp(reference, 0.0, 1.0) * uShadowSlice.y;
}
