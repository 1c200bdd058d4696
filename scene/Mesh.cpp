#include "Mesh.h"

#include "ShaderConstants.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

bool smoothShaded(const Mesh& mesh)
{
    // A lean of asin(kOwnFacetCosine), 0.057 degrees, already turns a facet away from a light its
    // normals face: nine tenths of it counts, well above a float normal's rounding. Either side,
    // as a mesh's normals may face against its winding.
    const double kFlat = std::cos(0.9 * std::asin(double(kOwnFacetCosine)));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex* v[3];
        for (std::size_t k = 0; k < 3; ++k)
            v[k] = mesh.indices[t + k] < mesh.vertices.size() ? &mesh.vertices[mesh.indices[t + k]] : nullptr;
        if (!v[0] || !v[1] || !v[2])
            continue;
        const glm::dvec3 a(v[0]->position);
        const glm::dvec3 facet = glm::cross(glm::dvec3(v[1]->position) - a, glm::dvec3(v[2]->position) - a);
        const double area = glm::length(facet);
        if (!(area > 0.0))
            continue;
        for (const Vertex* vertex : v) {
            const double length = glm::length(glm::dvec3(vertex->normal));
            if (length > 0.0 && std::abs(glm::dot(glm::dvec3(vertex->normal), facet)) < kFlat * length * area)
                return true;
        }
    }
    return false;
}

std::optional<MeshPlane> flatPlane(const Mesh& mesh)
{
    // The normal of the largest triangle: the one rounding disturbs least.
    const auto position = [&](std::uint32_t i) { return glm::dvec3(mesh.vertices.at(i).position); };
    glm::dvec3 normal(0.0);
    double largest = 0.0;
    glm::dvec3 lo(0.0), hi(0.0);
    for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
        const glm::dvec3 p(mesh.vertices[k].position);
        lo = k == 0 ? p : glm::min(lo, p);
        hi = k == 0 ? p : glm::max(hi, p);
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = position(mesh.indices[t]);
        const glm::dvec3 n = glm::cross(position(mesh.indices[t + 1]) - a, position(mesh.indices[t + 2]) - a);
        if (glm::length(n) > largest) {
            largest = glm::length(n);
            normal = n;
        }
    }
    if (largest <= 0.0 || mesh.vertices.empty())
        return std::nullopt;
    normal /= largest;
    const glm::dvec3 point = position(mesh.indices[0]);
    // Flat to a millionth of its size, and every triangle with area turned the same way.
    const double tolerance = 1e-6 * std::max(glm::length(hi - lo), 1e-30);
    for (const Vertex& v : mesh.vertices) {
        if (std::abs(glm::dot(glm::dvec3(v.position) - point, normal)) > tolerance)
            return std::nullopt;
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = position(mesh.indices[t]);
        if (glm::dot(glm::cross(position(mesh.indices[t + 1]) - a, position(mesh.indices[t + 2]) - a), normal) < 0.0)
            return std::nullopt;
    }
    return MeshPlane{point, normal};
}

} // namespace shadowlab

namespace shadowlab::meshes {

namespace {

void addQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec2 uvScale = {1.0f, 1.0f})
{
    // a, b, c, d counter-clockwise seen from the front.
    const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
    const auto base = std::uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({a, n, glm::vec2(0.0f, 0.0f) * uvScale});
    mesh.vertices.push_back({b, n, glm::vec2(1.0f, 0.0f) * uvScale});
    mesh.vertices.push_back({c, n, glm::vec2(1.0f, 1.0f) * uvScale});
    mesh.vertices.push_back({d, n, glm::vec2(0.0f, 1.0f) * uvScale});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void addTriangle(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c)
{
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const auto base = std::uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({a, n, {0.0f, 0.0f}});
    mesh.vertices.push_back({b, n, {1.0f, 0.0f}});
    mesh.vertices.push_back({c, n, {0.5f, 1.0f}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
}

// Indices for a (columns + 1) x (rows + 1) grid of vertices laid out row by row.
void addGridIndices(Mesh& mesh, int columns, int rows)
{
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const auto i0 = std::uint32_t(r * (columns + 1) + c);
            const auto i1 = i0 + 1;
            const auto i2 = i0 + std::uint32_t(columns + 1);
            const auto i3 = i2 + 1;
            mesh.indices.insert(mesh.indices.end(), {i0, i2, i1, i1, i2, i3});
        }
    }
}

} // namespace

Mesh plane(float halfSize, float uvRepeat)
{
    Mesh mesh;
    mesh.convex = true;
    const float h = halfSize;
    addQuad(mesh, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}, {uvRepeat, uvRepeat});
    return mesh;
}

Mesh cube()
{
    Mesh mesh;
    mesh.convex = true;
    const glm::vec3 p[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    addQuad(mesh, p[4], p[5], p[6], p[7]); // +z
    addQuad(mesh, p[1], p[0], p[3], p[2]); // -z
    addQuad(mesh, p[5], p[1], p[2], p[6]); // +x
    addQuad(mesh, p[0], p[4], p[7], p[3]); // -x
    addQuad(mesh, p[7], p[6], p[2], p[3]); // +y
    addQuad(mesh, p[0], p[1], p[5], p[4]); // -y
    return mesh;
}

Mesh sphere(int segments, int rings)
{
    segments = std::max(segments, 3);
    rings = std::max(rings, 3);
    Mesh mesh;
    mesh.convex = true;
    for (int r = 0; r <= rings; ++r) {
        const float v = float(r) / float(rings);
        const float theta = v * glm::pi<float>();
        for (int s = 0; s <= segments; ++s) {
            const float u = float(s) / float(segments);
            const float phi = u * glm::two_pi<float>();
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            mesh.vertices.push_back({n, n, {u, 1.0f - v}});
        }
    }
    addGridIndices(mesh, segments, rings);
    return mesh;
}

Mesh torus(float major, float minor, int segments, int sides)
{
    segments = std::max(segments, 3);
    sides = std::max(sides, 3);
    Mesh mesh;
    for (int i = 0; i <= sides; ++i) {
        const float v = float(i) / float(sides);
        const float psi = v * glm::two_pi<float>();
        for (int j = 0; j <= segments; ++j) {
            const float u = float(j) / float(segments);
            const float phi = u * glm::two_pi<float>();
            const glm::vec3 ringDir(std::cos(phi), 0.0f, -std::sin(phi));
            const glm::vec3 n = std::cos(psi) * ringDir + glm::vec3(0.0f, std::sin(psi), 0.0f);
            mesh.vertices.push_back({ringDir * major + n * minor, n, {u * 4.0f, v}});
        }
    }
    // Rows advance in psi, columns in phi; this winding keeps normals outward.
    for (int r = 0; r < sides; ++r) {
        for (int c = 0; c < segments; ++c) {
            const auto i0 = std::uint32_t(r * (segments + 1) + c);
            const auto i1 = i0 + 1;
            const auto i2 = i0 + std::uint32_t(segments + 1);
            const auto i3 = i2 + 1;
            mesh.indices.insert(mesh.indices.end(), {i0, i1, i2, i1, i3, i2});
        }
    }
    return mesh;
}

Mesh pyramid()
{
    Mesh mesh;
    mesh.convex = true;
    const glm::vec3 apex(0, 1, 0);
    const glm::vec3 b[4] = {{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}};
    for (int i = 0; i < 4; ++i)
        addTriangle(mesh, b[i], b[(i + 1) % 4], apex);
    addQuad(mesh, b[3], b[2], b[1], b[0]);
    return mesh;
}

Mesh card(glm::vec2 uvRepeat)
{
    Mesh mesh;
    const glm::vec3 corners[4] = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
    for (const float side : {1.0f, -1.0f}) {
        const auto base = std::uint32_t(mesh.vertices.size());
        for (const glm::vec3& c : corners)
            mesh.vertices.push_back({c, {0.0f, 0.0f, side}, glm::vec2((c.x + 1.0f) * 0.5f, (1.0f - c.y) * 0.5f) * uvRepeat});
        if (side > 0.0f)
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        else
            mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
    return mesh;
}

} // namespace shadowlab::meshes
