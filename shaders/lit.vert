// Lit pass: camera-relative attributes for lighting plus the position in shadow-map space.
// Positions are relative to the camera (translation folded in double precision on the CPU),
// so a scene far from the origin keeps float precision where the eye is.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;            // object -> world, translated so the camera is at the origin
uniform mat3 uNormalMatrix;
uniform mat4 uModelViewProjection;
uniform mat4 uShadowModel;      // object -> shadow texture space (xy and depth in [0, 1])

out vec3 vPosition;             // camera-relative world position
out vec3 vNormal;
out vec2 vUv;
out vec4 vShadowCoord;

void main()
{
    vec4 position = vec4(aPosition, 1.0);
    vPosition = vec3(uModel * position);
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
    vShadowCoord = uShadowModel * position;
    gl_Position = uModelViewProjection * position;
}
