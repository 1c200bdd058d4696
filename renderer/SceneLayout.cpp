#include "SceneLayout.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <map>
#include <tuple>

namespace shadowlab {

namespace {

// From this many objects a scene is drawn in batches; below it every object keeps its own draw
// (and its own culling and shadow reach, which a few draws make cheap).
constexpr std::size_t kBatchFrom = 64;
// Cells per side of the grid batches are cut by: draws stay at most cells² per material.
constexpr int kBatchCells = 8;
// Objects with larger meshes draw alone: merging copies every vertex.
constexpr std::size_t kMaxBatchedVertices = 4096;

DrawItem aloneItem(const Scene& scene, std::size_t i, const Bounds& bounds, bool smooth)
{
    const SceneObject& object = scene.objects[i];
    DrawItem item;
    item.objects = {i};
    item.bounds = bounds;
    item.model = object.model;
    item.normalMatrix = glm::inverseTranspose(glm::dmat3(object.model));
    item.baseColour = object.baseColour;
    item.castsShadow = object.castsShadow;
    item.receivesShadow = object.receivesShadow;
    item.alphaCutoff = textureAlphaCutoff(object);
    item.mesh = object.mesh;
    item.smoothShaded = smooth;
    return item;
}

} // namespace

SceneLayout::SceneLayout(const Scene& scene)
{
    for (const Mesh& mesh : scene.meshes) {
        Bounds local;
        for (const Vertex& v : mesh.vertices)
            local.extend(glm::dvec3(v.position));
        m_meshBounds.push_back(local);
    }
    for (const SceneObject& object : scene.objects) {
        const Bounds& local = m_meshBounds.at(std::size_t(object.mesh));
        m_objectBounds.push_back(local.transformed(object.model));
        m_objectModels.push_back(object.model);
        m_objectMeshes.push_back(object.mesh);
        m_swept.push_back(object.motion ? std::optional(object.motion->sweptBounds(local)) : std::nullopt);
        if (m_swept.back())
            m_moving.push_back(m_swept.size() - 1);
        m_sampled.push_back(object.motion ? std::optional(object.motion->sweptBounds(local, false)) : std::nullopt);
        m_bounds.extend(m_swept.back() ? *m_swept.back() : m_objectBounds.back());
    }
    for (const Mesh& mesh : scene.meshes) {
        m_meshPlanes.push_back(flatPlane(mesh));
        m_meshSmooth.push_back(smoothShaded(mesh));
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        m_objectFloors.push_back(floorPlane(i));
    layOutItems(scene);
}

std::optional<WorldPlane> SceneLayout::objectPlane(std::size_t i) const
{
    const std::optional<MeshPlane>& plane = m_meshPlanes.at(std::size_t(m_objectMeshes.at(i)));
    if (!plane)
        return std::nullopt;
    // By two edges through the model, so a mirroring model turns the side it faces too.
    const glm::dmat4& model = m_objectModels.at(i);
    const glm::dvec3 u = glm::abs(plane->normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 e1 = glm::cross(plane->normal, u), e2 = glm::cross(plane->normal, e1);
    const auto world = [&](const glm::dvec3& p) { return glm::dvec3(model * glm::dvec4(p, 1.0)); };
    const glm::dvec3 origin = world(plane->point);
    const glm::dvec3 normal = glm::cross(world(plane->point + e1) - origin, world(plane->point + e2) - origin);
    if (!(glm::length(normal) > 0.0))
        return std::nullopt;
    return WorldPlane{origin, glm::normalize(normal)};
}

std::optional<WorldPlane> SceneLayout::floorPlane(std::size_t i) const
{
    std::optional<WorldPlane> plane = objectPlane(i);
    if (!plane || moves(i))
        return std::nullopt;
    // Every other object's box on the front side, or on the plane within rounding.
    const double tolerance = 1e-6 * std::max(glm::length(m_bounds.max - m_bounds.min), 1e-30);
    for (std::size_t j = 0; j < m_objectBounds.size(); ++j) {
        if (j == i)
            continue;
        for (const glm::dvec3& c : m_sampled[j] ? m_sampled[j]->corners() : objectBox(j)) {
            if (glm::dot(c - plane->point, plane->normal) < -tolerance)
                return std::nullopt;
        }
    }
    return plane;
}

bool shadowsNothing(const DrawItem& item, const LightFrame& light)
{
    if (!item.floor)
        return false;
    const glm::dvec3 toLight = light.perspective ? light.position - item.floor->point : -light.direction;
    return glm::dot(toLight, item.floor->normal) > 0.0;
}

std::array<glm::dvec3, 8> SceneLayout::objectBox(std::size_t i) const
{
    const glm::dmat4& model = m_objectModels.at(i);
    std::array<glm::dvec3, 8> corners = m_meshBounds.at(std::size_t(m_objectMeshes.at(i))).corners();
    for (glm::dvec3& c : corners)
        c = glm::dvec3(model * glm::dvec4(c, 1.0));
    return corners;
}

void SceneLayout::layOutItems(const Scene& scene)
{
    const auto& objects = scene.objects;
    m_itemOf.assign(objects.size(), 0);
    // Batches: per cell of a grid over the scene's ground plan and per material and flags.
    // Flat one-sided meshes (grounds) stay alone: the shadow reach knows them by their plane.
    using Key = std::tuple<int, int, int, bool, bool, float>;    // cell, texture kind, image, casts, receives, alpha cut-off
    std::map<Key, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& object = objects[i];
        const Mesh& mesh = scene.meshes.at(std::size_t(object.mesh));
        // A moving object draws alone too: its draw item follows it.
        if (objects.size() < kBatchFrom || mesh.vertices.size() > kMaxBatchedVertices || m_meshPlanes.at(std::size_t(object.mesh)) || moves(i)) {
            m_itemOf[i] = m_items.size();
            m_items.push_back(aloneItem(scene, i, m_objectBounds[i], m_meshSmooth.at(std::size_t(object.mesh))));
            m_items.back().floor = m_objectFloors[i];
            m_items.back().moves = moves(i);
            continue;
        }
        const glm::dvec3 size = glm::max(m_bounds.max - m_bounds.min, glm::dvec3(1e-30));
        const glm::dvec3 at = (m_objectBounds[i].center() - m_bounds.min) / size;
        const int cx = std::clamp(int(at.x * kBatchCells), 0, kBatchCells - 1);
        const int cz = std::clamp(int(at.z * kBatchCells), 0, kBatchCells - 1);
        groups[{cz * kBatchCells + cx, int(object.texture), object.image, object.castsShadow, object.receivesShadow,
                textureAlphaCutoff(object)}].push_back(i);
    }
    for (const auto& [key, members] : groups) {
        if (members.size() == 1) {
            m_itemOf[members.front()] = m_items.size();
            const std::size_t i = members.front();
            m_items.push_back(aloneItem(scene, i, m_objectBounds[i], m_meshSmooth.at(std::size_t(objects[i].mesh))));
            continue;
        }
        for (std::size_t i : members)
            m_itemOf[i] = m_items.size();
        DrawItem item;
        item.objects = members;
        for (std::size_t i : members) {
            item.bounds.extend(m_objectBounds[i]);
            item.smoothShaded = item.smoothShaded || m_meshSmooth.at(std::size_t(objects[i].mesh));
        }
        item.model = glm::translate(glm::dmat4(1.0), item.bounds.center());
        item.castsShadow = std::get<3>(key);
        item.receivesShadow = std::get<4>(key);
        item.alphaCutoff = std::get<5>(key);
        item.batch = true;
        item.mesh = m_batchCount++;
        m_items.push_back(std::move(item));
    }
}

void SceneLayout::pose(const Scene& scene, const std::vector<std::size_t>& moved)
{
    for (std::size_t i : moved) {
        const SceneObject& object = scene.objects.at(i);
        m_objectModels.at(i) = object.model;
        m_objectBounds.at(i) = m_meshBounds.at(std::size_t(object.mesh)).transformed(object.model);
        DrawItem& item = m_items.at(m_itemOf.at(i));
        item.bounds = m_objectBounds[i];
        item.model = object.model;
        item.normalMatrix = glm::inverseTranspose(glm::dmat3(object.model));
    }
}

BatchGeometry SceneLayout::batchGeometry(const Scene& scene, const DrawItem& item)
{
    BatchGeometry g;
    const glm::dvec3 origin(item.model[3]);
    for (std::size_t i : item.objects) {
        const SceneObject& object = scene.objects.at(i);
        const Mesh& mesh = scene.meshes.at(std::size_t(object.mesh));
        const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(object.model));
        const auto base = std::uint32_t(g.vertices.size());
        for (const Vertex& v : mesh.vertices) {
            const glm::dvec3 p = glm::dvec3(object.model * glm::dvec4(glm::dvec3(v.position), 1.0)) - origin;
            const glm::dvec3 n = normalMatrix * glm::dvec3(v.normal);
            const double length = glm::length(n);
            g.vertices.push_back({{glm::vec3(p), glm::vec3(length > 0.0 ? n / length : n), v.uv}, object.baseColour});
        }
        // A mirroring placement turns the winding: keep front faces counter-clockwise.
        const bool mirrored = glm::determinant(glm::dmat3(object.model)) < 0.0;
        for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
            g.indices.push_back(base + mesh.indices[k]);
            g.indices.push_back(base + mesh.indices[mirrored ? k + 2 : k + 1]);
            g.indices.push_back(base + mesh.indices[mirrored ? k + 1 : k + 2]);
        }
    }
    return g;
}

} // namespace shadowlab
