// Moments pass: casters from the light, each fragment's linear depth in [0, 1] between the
// light volume's near and far planes (affine in view space, so its interpolation is exact for
// both projections). With uFarPlane it draws one triangle over the whole map at depth 1
// instead: where no caster is, the map holds the moments of the far plane. With ALPHA_CUTOUT
// the texture coordinates go on for the mask.
layout(location = 0) in vec3 aPosition;

uniform mat4 uLightModelViewProjection;
uniform vec2 uDepthRange;   // near and far of the light volume along its axis (perspective)
uniform bool uFarPlane;

out float vDepth;
#ifdef ALPHA_CUTOUT
layout(location = 2) in vec2 aUv;
out vec2 vUv;
#endif

void main()
{
    if (uFarPlane) {
        vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
        gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
        vDepth = 1.0;
        return;
    }
#ifdef ALPHA_CUTOUT
    vUv = aUv;
#endif
    gl_Position = uLightModelViewProjection * vec4(aPosition, 1.0);
#ifdef LIGHT_PERSPECTIVE
    vDepth = (gl_Position.w - uDepthRange.x) / (uDepthRange.y - uDepthRange.x);
#else
    vDepth = gl_Position.z / gl_Position.w * 0.5 + 0.5;
#endif
}
