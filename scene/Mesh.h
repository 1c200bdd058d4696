#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

// Indexed triangle list in object space, counter-clockwise front faces, unit normals.
struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    bool convex = false;        // no part can shadow another part (the light fit uses this)
};

namespace meshes {

// A square in the xz plane, normal +y, from -halfSize to +halfSize; UVs repeat `uvRepeat` times.
Mesh plane(float halfSize, float uvRepeat);
// An axis-aligned cube from -1 to 1, flat-shaded (24 vertices), UVs 0..1 per face.
Mesh cube();
// A unit sphere, `segments` around and `rings` from pole to pole (both >= 3).
Mesh sphere(int segments, int rings);
// A torus in the xz plane around +y: ring radius `major`, tube radius `minor`.
Mesh torus(float major, float minor, int segments, int sides);
// A square pyramid with base from -1 to 1 at y = -1 and apex at (0, 1, 0), flat-shaded.
Mesh pyramid();

} // namespace meshes

} // namespace shadowlab
