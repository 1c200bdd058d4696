// One triangle that covers the viewport, no vertex buffer; vUv spans [0, 1] over the
// viewport, mapped through uUvOffset/uUvScale so a view can zoom and pan.
uniform vec2 uUvOffset;
uniform vec2 uUvScale;

out vec2 vUv;

void main()
{
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    vUv = uUvOffset + corner * uUvScale;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
