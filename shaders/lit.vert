// Lit pass: world-space attributes for lighting plus the position in shadow-map space.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uModelViewProjection;
uniform mat4 uShadowModel;      // object -> shadow texture space (xy and depth in [0, 1])

out vec3 vWorldPosition;
out vec3 vNormal;
out vec2 vUv;
out vec4 vShadowCoord;

void main()
{
    vec4 position = vec4(aPosition, 1.0);
    vWorldPosition = vec3(uModel * position);
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
    vShadowCoord = uShadowModel * position;
    gl_Position = uModelViewProjection * position;
}
