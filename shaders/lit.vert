// Lit pass: camera-relative attributes for lighting plus the position in shadow-map space.
// Positions are relative to the camera (translation folded in double precision on the CPU),
// so a scene far from the origin keeps float precision where the eye is.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec3 aColour;   // the base colour: per vertex in a batch, else a constant

uniform mat4 uModel;            // object -> world, translated so the camera is at the origin
uniform mat3 uNormalMatrix;
uniform mat4 uModelViewProjection;
uniform mat4 uShadowModel;      // object -> shadow texture space (xy and depth in [0, 1])
uniform mat4 uShadowWorld;      // world -> shadow texture space; used on directions only
uniform float uNormalOffset;    // world units to move along the normal (per unit of w for a perspective light)

out vec3 vPosition;             // camera-relative world position
out vec3 vNormal;
out vec2 vUv;
out vec3 vColour;
// Receivers straddling the shadow reach are drawn by two variants of this shader, each on
// its side of a stencil mask: the same depth from both.
invariant gl_Position;
out vec4 vShadowCoord;
#ifdef FOOTPRINT_BIAS
// The unit normal as a step in shadow-map space, for the footprint's move (one view).
#ifdef LIGHT_PERSPECTIVE
out vec4 vShadowNormal;
#else
out vec3 vShadowNormal;
#endif
#endif

void main()
{
    vec4 position = vec4(aPosition, 1.0);
    vPosition = vec3(uModel * position);
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
    vColour = aColour;
    // Normal offset: look the shadow up from a point moved off the surface by a few texels,
    // so the lookup clears the surface's own depth where a depth bias would need to be huge.
    // Homogeneous coordinates make the offset a separate term (w = 0), which keeps the exact
    // object-space path for the position itself. A perspective texel grows with distance (w).
    vec4 shadowCoord = uShadowModel * position;
    float offset = uNormalOffset;
#ifdef LIGHT_PERSPECTIVE
    offset *= shadowCoord.w;
#endif
    float normalLength = length(vNormal);   // 0 only on a degenerate mesh: no offset, no NaN
    vec3 unitNormal = normalLength > 0.0 ? vNormal / normalLength : vec3(0.0);
    vec4 normalStep = uShadowWorld * vec4(unitNormal, 0.0);
    vShadowCoord = shadowCoord + normalStep * offset;
#ifdef FOOTPRINT_BIAS
#ifdef LIGHT_PERSPECTIVE
    vShadowNormal = normalStep;
#else
    vShadowNormal = normalStep.xyz;
#endif
#endif
    gl_Position = uModelViewProjection * position;
}
