// Light gizmo and light-volume wireframe: flat colour, blended so hidden edges can be faint.
in vec4 vColor;

out vec4 fragColor;

void main()
{
    fragColor = vColor;
}
