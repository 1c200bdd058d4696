#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

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

// A flat one-sided mesh (a ground, a wall): a point on the plane all its triangles lie in and
// the unit normal their winding gives, every triangle facing the same way. Nullopt for any
// other mesh. A light on the front side sees every triangle's front face, so culling front
// faces leaves nothing of it in the shadow map.
struct MeshPlane {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};
};
std::optional<MeshPlane> flatPlane(const Mesh& mesh);

// Whether the mesh's normals bend across its triangles (a smooth-shaded mesh): some vertex's
// normal leans from its triangle's normal (either side) by more than 0.05 degrees, nine tenths
// of the lean that kOwnFacetCosine turns a facet away by. Such a mesh is faceted under its
// shading: near the terminator a facet can face away from the light while its normals still
// face it (the lit pass's OWN_FACETS).
bool smoothShaded(const Mesh& mesh);

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
// A two-sided card (a leaf, a fence panel): the square from -1 to 1 in the xy plane, once facing
// +z and once facing -z (8 vertices), UVs 0..uvRepeat with v = 0 at the top, the same texel at
// the same point from both sides. For cut-out textures, seen and cast from either side. Both
// faces lie in one plane, so the lit face meets its own depth in the map at grazing light.
Mesh card(glm::vec2 uvRepeat = {1.0f, 1.0f});

} // namespace meshes

} // namespace shadowlab
