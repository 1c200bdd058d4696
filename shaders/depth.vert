// Shadow pass: positions only, straight into the light's clip space.
layout(location = 0) in vec3 aPosition;

uniform mat4 uLightModelViewProjection;

void main()
{
    gl_Position = uLightModelViewProjection * vec4(aPosition, 1.0);
}
