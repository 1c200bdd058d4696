// The lit pass's variant for receivers no caster reaches (core/ShadowReach.h): every tap would
// read the lit border or the far plane, so none is taken. Stands in for a technique's file.
float filterShadow(vec2 uv, float reference)
{
    return 1.0;
}
