// Camera depth prepass for contact shadows: casters' positions into the camera's clip space,
// with their distance along the view direction.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelViewProjection;
uniform mat4 uModel;            // object -> world, translated so the camera is at the origin
uniform vec3 uCameraForward;    // unit view direction

out float vViewDepth;
#ifdef ALPHA_CUTOUT
layout(location = 2) in vec2 aUv;
out vec2 vUv;
#endif

void main()
{
#ifdef ALPHA_CUTOUT
    vUv = aUv;
#endif
    vViewDepth = dot(vec3(uModel * vec4(aPosition, 1.0)), uCameraForward);
    gl_Position = uModelViewProjection * vec4(aPosition, 1.0);
}
