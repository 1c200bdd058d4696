// Lit pass: Blinn-Phong or Phong with a diffuse texture; the light term is scaled by the
// shadow visibility of the one lookup (shadow_lookup.glsl) and the technique's filter, and with
// CONTACT_SHADOWS the smaller of that and a march over the camera's depth. Ambient stays in shadow.
// With OWN_FACETS a smooth-shaded caster's facet that faces away from the light is in its own
// shadow, looked up or not (ownFacetVisibility).
// With MEASURE the same shadow term also goes to float targets for the accuracy
// measurement, so what is measured is exactly what is shaded, and with it the light terms
// that the shadow term scales, so the frame can be shaded again with the reference's.
// With ALPHA_CUTOUT a cut-out object's texels below its cut-off are not drawn (leaves, fences).
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
#ifdef FOOTPRINT_BIAS
#ifdef LIGHT_PERSPECTIVE
in vec4 vShadowNormal;
#else
in vec3 vShadowNormal;
#endif
#endif

uniform sampler2D uDiffuse;
#ifdef ALPHA_CUTOUT
uniform float uAlphaCutoff;     // a cut-out object's (textureAlphaCutoff): below it the surface is not there
#endif
uniform bool uReceives;     // false: the object is always lit
#include LitFrameBlock
#ifdef SHADOWS
#include "shadow_lookup.glsl"
#endif
#ifdef CONTACT_SHADOWS
#include "contact_shadows.glsl"
#endif

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

void main()
{
#ifdef TEXEL_DENSITY
    // Derivatives before any branch, where they are defined.
    vec3 mapCoord = vShadowCoord.xyz / vShadowCoord.w;
    vec2 texel = mapCoord.xy / uShadowTexel;
    vec2 tx = dFdx(texel), ty = dFdy(texel);
    float texelsPerPixel = sqrt(abs(tx.x * ty.y - tx.y * ty.x));
    bool inMap = vShadowCoord.w > 0.0 && all(greaterThanEqual(mapCoord.xy, vec2(0.0))) && all(lessThanEqual(mapCoord.xy, vec2(1.0)));
#ifdef VIRTUAL_MAP
    // A virtual map's texel is its level's: level 0's density, halved per level read.
    vec2 q0 = (uVirtualLight * vec4(vPosition, 1.0)).xy;
    vec2 dqx = dFdx(q0), dqy = dFdy(q0);
    float texelsPerPixelLevel0 = float(kVirtualPageTexels) * sqrt(abs(dqx.x * dqy.y - dqx.y * dqy.x));
#endif
#endif
    vec4 base = texture(uDiffuse, vUv);
#ifdef MEASURE
    vec3 geometric = normalize(cross(dFdx(vPosition), dFdy(vPosition)));
#endif
    vec3 albedo = base.rgb * vColour;
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

#if defined(SHADOWS) && defined(OUT_OF_REACH) && !defined(MEASURE) && !defined(SHOW_CASCADES) && !defined(TEXEL_DENSITY)
    // Out of every caster's reach a lookup reads lit, or unlit where the receiver faces away
    // from the light, and there the direct term is 0 already: the frame is the same without it,
    // and this variant then reads no shadow coordinate (what is measured still takes the lookup).
    // A smooth-shaded caster's facet that faces away is unlit either way (OWN_FACETS).
    float visibility = uReceives ? ownFacetVisibility(normal, toLight) : 1.0;
#elif defined(SHADOWS)
    float visibility = uReceives ? shadowVisibility(normal, toLight) : 1.0;
#else
    float visibility = 1.0;
#endif
#ifdef CONTACT_SHADOWS
    if (uReceives)
        visibility = min(visibility, contactVisibility(vPosition, toLight));
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
#ifdef SHADOW_ONLY
    // The shadow term alone: grey levels show a filter's partial shadow (a moiré over a lit
    // floor) that lighting and textures hide; surfaces facing away from the light are unlit by
    // their facing, not by a shadow, and say so in their own colour.
    fragColor = vec4(dot(normal, toLight) > 0.0 ? vec3(visibility) : vec3(0.16, 0.25, 0.55), 1.0);
#endif
#ifdef TEXEL_DENSITY
#ifdef VIRTUAL_MAP
    inMap = gViewIndex >= 0;
    texelsPerPixel = texelsPerPixelLevel0 * exp2(-float(max(gViewIndex, 0)));
#endif
    if (uReceives && inMap)
        fragColor.rgb = mix(fragColor.rgb, densityRamp(1.0 / max(texelsPerPixel, 1e-6)), 0.6);
#endif
#if defined(SHADOWS) && defined(SHOW_CASCADES)
    if (uReceives)
        fragColor.rgb = mix(fragColor.rgb, viewTint(gViewIndex) * (0.4 + 0.6 * fragColor.rgb), 0.45);
#endif
#ifdef ALPHA_CUTOUT
    // Last: every derivative above (the lookup's receiver plane and footprint, the march's
    // slope, implicit lods) is taken with the whole 2 x 2 quad still running.
    if (base.a < uAlphaCutoff)
        discard;
#endif
#ifdef MEASURE
    if (dot(geometric, normal) < 0.0)
        geometric = -geometric;
    measuredPosition = vec4(vPosition, visibility);
    measuredNormal = vec4(geometric, !uReceives ? 3.0 : (dot(normal, toLight) > 0.0 ? 1.0 : 2.0));
    measuredAmbient = ambient;
    measuredDirect = direct;
#endif
}
