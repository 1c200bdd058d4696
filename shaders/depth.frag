// Shadow pass: depth only; the rasteriser writes gl_FragCoord.z into the shadow map.
void main()
{
}
