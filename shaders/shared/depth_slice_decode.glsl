// A depth map drawn into slices (map.slices, renderer/DepthSlices.h): its last draw wrote depth
// d at slice.x + d * slice.y; from slice.z up lie the slices earlier draws left, which read
// beyond the far plane, as a cleared texel does. A stored value as conventional depth, at most 1.
float sliceDepthOf(float stored, vec3 slice)
{
    return stored >= slice.z ? 1.0f : min((stored - slice.x) / slice.y, 1.0f);
}
