// The shadow lookup shared by every filter technique, then the technique itself: the lit pass
// defines SHADOW_TECHNIQUE as the file its row of the technique table names (shadow/<key>.glsl),
// which defines float filterShadow(vec2 uv, float reference): 1 lit, 0 shadowed.
// Every compare tap is a hardware depth comparison (sampler2DShadow): the sampler's filter decides
// whether a tap is one texel (nearest) or a bilinear blend of four comparisons (linear).
// Outside the map the border depth of 1.0 makes every tap lit.

uniform sampler2DShadow uShadowMap;
uniform vec2 uShadowTexel;      // 1 / map size

float shadowTap(vec2 uv, float reference)
{
    return texture(uShadowMap, vec3(uv, reference));
}

#include SHADOW_TECHNIQUE
