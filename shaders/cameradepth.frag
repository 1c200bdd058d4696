// Camera depth prepass for contact shadows: the distance along the view, into the red channel
// for the nearest front faces and the green one for the nearest back faces (the colour mask
// picks the channel of each pass), so the march reads both in one lookup.
in float vViewDepth;

layout(location = 0) out vec2 viewDepth;

void main()
{
    viewDepth = vec2(vViewDepth);
}
