#include "GpuScene.h"

#include "ProceduralTexture.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstddef>
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

struct BatchVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec3 colour;
};

void setAttributes(GlFunctions* gl, GLsizei stride, bool colour)
{
    gl->glEnableVertexAttribArray(0);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, position)));
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, normal)));
    gl->glEnableVertexAttribArray(2);
    gl->glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, uv)));
    if (colour) {
        gl->glEnableVertexAttribArray(3);
        gl->glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BatchVertex, colour)));
    }
}

} // namespace

GpuScene::GpuScene(GlFunctions* gl, Scene scene) : m_gl(gl), m_es(QOpenGLContext::currentContext()->functions()), m_scene(std::move(scene))
{
    for (const SceneObject& object : m_scene.objects) {
        m_objectBounds.push_back(m_scene.worldBounds(object));
        m_bounds.extend(m_objectBounds.back());
    }
    for (const Mesh& mesh : m_scene.meshes) {
        m_meshPlanes.push_back(flatPlane(mesh));
        GpuMesh g{makeVertexArray(gl), makeBuffer(gl), makeBuffer(gl), GLsizei(mesh.indices.size())};
        gl->glBindVertexArray(g.vertexArray.id());
        gl->glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
        gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(Vertex)), mesh.vertices.data(), GL_STATIC_DRAW);
        gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
        gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                         GL_STATIC_DRAW);
        setAttributes(gl, sizeof(Vertex), false);
        const QString name = QStringLiteral("%1 mesh %2").arg(m_scene.name).arg(m_meshes.size());
        labelGlObject(GlLabelKind::VertexArray, g.vertexArray.id(), name);
        labelGlObject(GlLabelKind::Buffer, g.vertices.id(), name + QStringLiteral(": vertices"));
        labelGlObject(GlLabelKind::Buffer, g.indices.id(), name + QStringLiteral(": indices"));
        m_meshes.push_back(std::move(g));
    }
    buildDrawItems();
    m_hasCutouts = m_scene.hasCutouts();
    gl->glBindVertexArray(0);

    const auto upload = [gl](const QImage& image, const QString& label) {
        GlTexture texture = makeTexture(gl);
        gl->glBindTexture(GL_TEXTURE_2D, texture.id());
        gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, image.constBits());
        gl->glGenerateMipmap(GL_TEXTURE_2D);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        labelGlObject(GlLabelKind::Texture, texture.id(), label);
        return texture;
    };
    m_textures[std::size_t(TextureKind::Checker)] = upload(makeProceduralTexture(TextureKind::Checker), QStringLiteral("checker texture"));
    m_textures[std::size_t(TextureKind::Wood)] = upload(makeProceduralTexture(TextureKind::Wood), QStringLiteral("wood texture"));
    QImage white(1, 1, QImage::Format_RGBA8888);
    white.fill(Qt::white);
    m_textures[std::size_t(TextureKind::Flat)] = upload(white, QStringLiteral("flat colour texture"));
    for (const QImage& image : m_scene.images)
        m_images.push_back(upload(image.convertToFormat(QImage::Format_RGBA8888), QStringLiteral("%1 image %2").arg(m_scene.name).arg(m_images.size())));
    gl->glBindTexture(GL_TEXTURE_2D, 0);
}

GLuint GpuScene::texture(const SceneObject& object) const
{
    if (object.texture == TextureKind::Image && object.image >= 0 && std::size_t(object.image) < m_images.size())
        return m_images[std::size_t(object.image)].id();
    if (object.texture == TextureKind::Image)
        return m_textures[std::size_t(TextureKind::Flat)].id();
    return m_textures[std::size_t(object.texture)].id();
}

void GpuScene::buildDrawItems()
{
    const auto& objects = m_scene.objects;
    const auto alone = [&](std::size_t i) {
        const SceneObject& object = objects[i];
        DrawItem item;
        item.objects = {i};
        item.bounds = m_objectBounds[i];
        item.model = object.model;
        item.normalMatrix = glm::inverseTranspose(glm::dmat3(object.model));
        item.baseColour = object.baseColour;
        item.castsShadow = object.castsShadow;
        item.receivesShadow = object.receivesShadow;
        item.alphaCutoff = textureAlphaCutoff(object);
        item.mesh = object.mesh;
        return item;
    };
    // Batches: per cell of a grid over the scene's ground plan and per material and flags.
    // Flat one-sided meshes (grounds) stay alone: the shadow reach knows them by their plane.
    using Key = std::tuple<int, int, int, bool, bool, float>;    // cell, texture kind, image, casts, receives, alpha cut-off
    std::map<Key, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& object = objects[i];
        const Mesh& mesh = m_scene.meshes.at(std::size_t(object.mesh));
        if (objects.size() < kBatchFrom || mesh.vertices.size() > kMaxBatchedVertices || m_meshPlanes.at(std::size_t(object.mesh))) {
            m_items.push_back(alone(i));
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
            m_items.push_back(alone(members.front()));
            continue;
        }
        DrawItem item;
        item.objects = members;
        for (std::size_t i : members)
            item.bounds.extend(m_objectBounds[i]);
        const glm::dvec3 origin = item.bounds.center();
        item.model = glm::translate(glm::dmat4(1.0), origin);
        item.castsShadow = std::get<3>(key);
        item.receivesShadow = std::get<4>(key);
        item.alphaCutoff = std::get<5>(key);
        item.batch = true;
        std::vector<BatchVertex> vertices;
        std::vector<std::uint32_t> indices;
        for (std::size_t i : members) {
            const SceneObject& object = objects[i];
            const Mesh& mesh = m_scene.meshes.at(std::size_t(object.mesh));
            const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(object.model));
            const auto base = std::uint32_t(vertices.size());
            for (const Vertex& v : mesh.vertices) {
                const glm::dvec3 p = glm::dvec3(object.model * glm::dvec4(glm::dvec3(v.position), 1.0)) - origin;
                const glm::dvec3 n = normalMatrix * glm::dvec3(v.normal);
                const double length = glm::length(n);
                vertices.push_back({glm::vec3(p), glm::vec3(length > 0.0 ? n / length : n), v.uv, object.baseColour});
            }
            // A mirroring placement turns the winding: keep front faces counter-clockwise.
            const bool mirrored = glm::determinant(glm::dmat3(object.model)) < 0.0;
            for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
                indices.push_back(base + mesh.indices[k]);
                indices.push_back(base + mesh.indices[mirrored ? k + 2 : k + 1]);
                indices.push_back(base + mesh.indices[mirrored ? k + 1 : k + 2]);
            }
        }
        GpuMesh g{makeVertexArray(m_gl), makeBuffer(m_gl), makeBuffer(m_gl), GLsizei(indices.size())};
        m_gl->glBindVertexArray(g.vertexArray.id());
        m_gl->glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
        m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(BatchVertex)), vertices.data(), GL_STATIC_DRAW);
        m_gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
        m_gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), GL_STATIC_DRAW);
        setAttributes(m_gl, sizeof(BatchVertex), true);
        labelGlObject(GlLabelKind::VertexArray, g.vertexArray.id(), QStringLiteral("%1 batch %2").arg(m_scene.name).arg(m_batches.size()));
        item.mesh = int(m_batches.size());
        m_batches.push_back(std::move(g));
        m_items.push_back(std::move(item));
    }
}

void GpuScene::draw(const DrawItem& item, bool colour) const
{
    const GpuMesh& mesh = item.batch ? m_batches.at(std::size_t(item.mesh)) : m_meshes.at(std::size_t(item.mesh));
    m_gl->glBindVertexArray(mesh.vertexArray.id());
    if (colour && !item.batch)
        m_es->glVertexAttrib3f(3, item.baseColour.r, item.baseColour.g, item.baseColour.b);
    m_gl->glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
}

} // namespace shadowlab
