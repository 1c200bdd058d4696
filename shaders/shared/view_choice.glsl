// The light rig's choice of view for a receiver, which the lit pass makes per pixel and the
// texel density measure (lab/TexelDensity) makes again.

// A point light's cube face for the direction d from the light: +x, -x, +y, -y, +z, -z
// (core/ShadowViews.cpp orders the faces so).
int cubeFace(vec3 d)
{
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

// The cascade a receiver at view depth `depth` (along the camera they were fitted to) reads:
// the first of `count` whose far end, `far`, lies at or beyond it; -1 beyond the last
// (shadow.distance), where nothing is looked up.
int cascadeIndex(float depth, vec4 far, int count)
{
    for (int i = 0; i < count; ++i) {
        if (depth <= far[i])
            return i;
    }
    return -1;
}
