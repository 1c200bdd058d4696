// GPU reduction of a virtual map's page requests (virtual_request.frag), as far as GL 3.3 goes
// without image atomics: one point per request pixel, drawn on the texel of the page it asks for
// in a target of one flag per page of every level's window (a window's width wide, as many rows
// a level). The read-back is then a byte per page, not a word per pixel, and duplicates are
// gone. Pixels that ask for nothing are sent outside the target. (With GL 4.3 a compute pass
// could append the flagged pages to a list of a few hundred entries.)
uniform usampler2D uRequests;
uniform int uRequestWidth;
uniform int uLevels;

void main()
{
    ivec2 at = ivec2(gl_VertexID % uRequestWidth, gl_VertexID / uRequestWidth);
    uint request = texelFetch(uRequests, at, 0).r;
    if (request == 0u) {
        gl_Position = vec4(2.0, 2.0, 0.0, 1.0);     // clipped: no flag
        return;
    }
    const uint n = uint(kVirtualLevelPages);        // pages per side of a level's window
    uint index = request - 1u;                      // level * n² + y * n + x
    uint level = index / (n * n);
    vec2 texel = vec2(float(index % n), float(level * n + (index / n) % n)) + 0.5;
    gl_Position = vec4(texel / vec2(float(n), float(n) * float(uLevels)) * 2.0 - 1.0, 0.0, 1.0);
}
