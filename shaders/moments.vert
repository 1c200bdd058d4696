// Moments pass: casters from the light, each fragment's depth in [0, 1] between the light
// volume's near and far planes: for a perspective light its distance along the axis (affine in
// view space, so interpolated exactly); otherwise the depth the depth pass stores, z / w divided
// per fragment, which a warped map (light.warp = lispsm, w varying over the map) needs. With uFarPlane it draws one triangle over the whole map at depth 1
// instead: where no caster is, the map holds the moments of the far plane. With ALPHA_CUTOUT
// the texture coordinates go on for the mask.
layout(location = 0) in vec3 aPosition;

uniform mat4 uLightModelViewProjection;
uniform vec2 uDepthRange;   // near and far of the light volume along its axis (perspective)
uniform bool uFarPlane;

#ifdef LIGHT_PERSPECTIVE
out float vDepth;
#else
out vec2 vClipDepth;        // clip z and w: both affine, so interpolated exactly
#endif
#ifdef ALPHA_CUTOUT
layout(location = 2) in vec2 aUv;
out vec2 vUv;
#endif

void main()
{
    if (uFarPlane) {
        vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
        gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
#ifdef LIGHT_PERSPECTIVE
        vDepth = 1.0;
#else
        vClipDepth = vec2(1.0);
#endif
        return;
    }
#ifdef ALPHA_CUTOUT
    vUv = aUv;
#endif
    gl_Position = uLightModelViewProjection * vec4(aPosition, 1.0);
#ifdef LIGHT_PERSPECTIVE
    vDepth = (gl_Position.w - uDepthRange.x) / (uDepthRange.y - uDepthRange.x);
#else
    vClipDepth = gl_Position.zw;
#endif
}
