// Lit pass: Blinn-Phong or Phong with a diffuse texture; the light term is scaled by the
// shadow visibility from the filter in shadow_filters.glsl. Ambient stays in shadow.
// With MEASURE the same shadow term also goes to float targets for the accuracy
// measurement, so what is measured is exactly what is shaded, and with it the light terms
// that the shadow term scales, so the frame can be shaded again with the reference's.
// With TEXEL_DENSITY receivers inside the light's volume are tinted by how many screen pixels
// one shadow texel covers (densityRamp), from the screen-space derivatives of the map position.
#include "shadow_filters.glsl"
#ifdef TEXEL_DENSITY
#include "ramp.glsl"
#endif

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vColour;            // multiplies the texture: white for presets, a material's base colour for models
in vec4 vShadowCoord;

uniform sampler2D uDiffuse;
uniform bool uReceives;     // false: the object is always lit
uniform vec3 uLightPosition;    // camera-relative
uniform vec3 uLightDirection;   // unit, from the light toward its target
uniform float uBiasSlope;       // per unit of (1 - N.L); world units (depth units with BIAS_DEPTH)
uniform float uBiasMin;         // world units (depth units with BIAS_DEPTH)
uniform mat4 uShadowWorld;      // world -> shadow texture space; used on directions only

#ifdef LIGHT_SPOT
uniform vec2 uSpotCone;         // cosines of the cone's half-angle and of where its falloff starts
#endif
#include "shadow_views.glsl"

layout(location = 0) out vec4 fragColor;
#ifdef MEASURE
layout(location = 1) out vec4 measuredPosition;    // camera-relative position, visibility
layout(location = 2) out vec4 measuredNormal;      // geometric normal, 1 facing the light / 2 away / 3 not receiving
layout(location = 3) out vec3 measuredAmbient;     // the frame is ambient + visibility * direct, so it can be
layout(location = 4) out vec3 measuredDirect;      // shaded again with the reference's visibility
#endif

vec3 directionToLight(vec3 position)
{
#ifdef LIGHT_PERSPECTIVE
    return normalize(uLightPosition - position);
#else
    return -uLightDirection;
#endif
}

// Visibility where no lookup is needed, or -1 where it is: outside the light's volume is lit,
// facing away from the light is unlit anyway.
float visibilityWithoutLookup(vec3 coord, float facing)
{
    if (vShadowCoord.w <= 0.0)
        return 1.0;             // behind a perspective light: outside its volume
#ifdef REVERSED_Z
    if (coord.z < 0.0)
        return 1.0;             // beyond the far plane (depth 0 when reversed) is lit
#else
    if (coord.z > 1.0)
        return 1.0;             // beyond the far plane is lit
#endif
    if (facing <= 0.0)
        return 0.0;
    // Outside the map's square every tap would read the lit border.
    return all(greaterThanEqual(coord.xy, vec2(0.0))) && all(lessThanEqual(coord.xy, vec2(1.0))) ? -1.0 : 1.0;
}

float shadowLookup(vec3 normal, vec3 toLight)
{
    // (1 - N.L) <= 1: bounded at grazing angles, where slope * tan(theta) would explode.
    float bias = max(uBiasSlope * (1.0 - dot(normal, toLight)), uBiasMin);
    // For the wide filters: a tap d world units away on this receiver's plane lies up to
    // d tan(theta) nearer the light; gGrowth is that in depth per world unit (tan capped at 10,
    // where N.L and so the light term is nearly 0 anyway).
    float cosTheta = clamp(dot(normal, toLight), 0.1, 1.0);    // rounding can put N.L above 1: no NaN
    vec4 alongRay = uShadowWorld * vec4(toLight, 0.0);
    float depthPerWorld = (alongRay.z * vShadowCoord.w - vShadowCoord.z * alongRay.w) / (vShadowCoord.w * vShadowCoord.w);
    gGrowth = depthPerWorld * sqrt(max(1.0 - cosTheta * cosTheta, 0.0)) / cosTheta;
    gShadowW = vShadowCoord.w;
    vec3 coord = vShadowCoord.xyz / vShadowCoord.w;
#ifdef BIAS_DEPTH
#ifdef REVERSED_Z
    return filterShadow(coord.xy, coord.z + bias);  // nearer the light is greater
#else
    return filterShadow(coord.xy, coord.z - bias);
#endif
#else
#if defined(BIAS_TEXEL) && defined(LIGHT_PERSPECTIVE)
    bias *= vShadowCoord.w;     // a perspective texel grows with the distance from the light
#endif
    // Compare from a point moved toward the light by `bias` world units: on the ray to the
    // light, so it stays on the same texel, and the same offset whatever the depth range.
    vec4 moved = vShadowCoord + uShadowWorld * vec4(toLight * bias, 0.0);
    return filterShadow(coord.xy, moved.z / moved.w);
#endif
}

float shadowVisibility(vec3 normal, vec3 toLight)
{
#ifdef SHADOWS
    vec3 coord = vShadowCoord.xyz / vShadowCoord.w;
#ifdef RECEIVER_PLANE
    // The receiver's depth as a plane over the map, from its screen-space derivatives (taken
    // before any branch, where they are defined): depth change per uv unit. A degenerate
    // footprint (the plane seen edge-on from the camera) gets a flat plane.
    vec3 dx = dFdx(coord), dy = dFdy(coord);
    float det = dx.x * dy.y - dx.y * dy.x;
    gReceiverSlope = abs(det) > 1e-20 ? vec2(dx.z * dy.y - dx.y * dy.z, dx.x * dy.z - dx.z * dy.x) / det : vec2(0.0);
#endif
    float visibility = visibilityWithoutLookup(coord, dot(normal, toLight));
    // A loop run once or not at all, meant to let a group of pixels that needs no lookup skip
    // it. On Mesa 22.3's llvmpipe it does not (nor does a branch): the body runs for the whole
    // group, measured. Receivers no caster reaches skip it by being drawn with a variant that
    // has no lookup at all (core/ShadowReach.h); on a GPU this costs nothing.
    for (int lookups = visibility < 0.0 ? 1 : 0; lookups > 0; --lookups)
        visibility = shadowLookup(normal, toLight);
    return visibility;
#else
    return 1.0;
#endif
}

void main()
{
#ifdef TEXEL_DENSITY
    // Derivatives before any branch, where they are defined.
    vec3 mapCoord = vShadowCoord.xyz / vShadowCoord.w;
    vec2 texel = mapCoord.xy / uShadowTexel;
    vec2 tx = dFdx(texel), ty = dFdy(texel);
    float texelsPerPixel = sqrt(abs(tx.x * ty.y - tx.y * ty.x));
    bool inMap = vShadowCoord.w > 0.0 && all(greaterThanEqual(mapCoord.xy, vec2(0.0))) && all(lessThanEqual(mapCoord.xy, vec2(1.0)));
#endif
    vec3 albedo = texture(uDiffuse, vUv).rgb * vColour;
    vec3 normal = normalize(vNormal);
    vec3 toLight = directionToLight(vPosition);
    vec3 toEye = normalize(-vPosition);

    float diffuse = max(dot(normal, toLight), 0.0);
    // The exponents by squaring: pow() is exp2(log2()) in software rasterisers, which costs
    // more than the rest of the lighting.
#ifdef SHADING_PHONG
    float specular = max(dot(toEye, reflect(-toLight, normal)), 0.0);
    specular *= specular;
    specular *= specular;
    specular *= specular;       // ^8
#else
    float specular = max(dot(normal, normalize(toLight + toEye)), 0.0);
    specular *= specular;
    specular *= specular;
    specular *= specular;
    specular *= specular;
    specular *= specular;       // ^32
#endif
    if (diffuse <= 0.0)
        specular = 0.0;

#ifdef SHADOW_VIEWS
    float visibility = uReceives ? shadowViewsVisibility(normal, toLight) : 1.0;
#else
    float visibility = uReceives ? shadowVisibility(normal, toLight) : 1.0;
#endif
    vec3 ambient = 0.3 * albedo;
    vec3 direct = diffuse * albedo + specular * vec3(0.3);
#ifdef LIGHT_SPOT
    // Unlit outside the cone, fading over its rim; the measured term is the shadow inside the
    // cone and 0 outside, as the reference traces it.
    float spotCosine = dot(-toLight, uLightDirection);
    direct *= uSpotCone.y > uSpotCone.x ? smoothstep(uSpotCone.x, uSpotCone.y, spotCosine) : step(uSpotCone.x, spotCosine);
    if (spotCosine <= uSpotCone.x)
        visibility = 0.0;
#endif
    fragColor = vec4(ambient + visibility * direct, 1.0);
#ifdef TEXEL_DENSITY
    if (uReceives && inMap)
        fragColor.rgb = mix(fragColor.rgb, densityRamp(1.0 / max(texelsPerPixel, 1e-6)), 0.6);
#endif
#if defined(SHADOW_VIEWS) && defined(SHOW_CASCADES)
    if (uReceives)
        fragColor.rgb = mix(fragColor.rgb, viewTint(gViewIndex) * (0.4 + 0.6 * fragColor.rgb), 0.45);
#endif
#ifdef MEASURE
    vec3 geometric = normalize(cross(dFdx(vPosition), dFdy(vPosition)));
    if (dot(geometric, normal) < 0.0)
        geometric = -geometric;
    measuredPosition = vec4(vPosition, visibility);
    measuredNormal = vec4(geometric, !uReceives ? 3.0 : (dot(normal, toLight) > 0.0 ? 1.0 : 2.0));
    measuredAmbient = ambient;
    measuredDirect = direct;
#endif
}
