// Shadow pass: positions only, straight into the light's clip space (with ALPHA_CUTOUT the
// texture coordinates too, for the mask).
layout(location = 0) in vec3 aPosition;
#ifdef ALPHA_CUTOUT
layout(location = 2) in vec2 aUv;
out vec2 vUv;
#endif

uniform mat4 uLightModelViewProjection;

void main()
{
#ifdef ALPHA_CUTOUT
    vUv = aUv;
#endif
    gl_Position = uLightModelViewProjection * vec4(aPosition, 1.0);
}
