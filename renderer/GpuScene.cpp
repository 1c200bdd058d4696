#include "GpuScene.h"

#include "ProceduralTexture.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <algorithm>
#include <cstddef>

namespace shadowlab {

namespace {

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

GpuScene::GpuScene(GlFunctions* gl, Scene scene)
    : m_gl(gl), m_es(QOpenGLContext::currentContext()->functions()), m_scene(std::move(scene)), m_layout(m_scene)
{
    for (const Mesh& mesh : m_scene.meshes) {
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
    uploadBatches();
    m_hasCutouts = m_scene.hasCutouts();
    m_hasSmoothCasters = std::any_of(drawItems().begin(), drawItems().end(), [](const DrawItem& item) { return item.castsShadow && item.smoothShaded; });
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

void GpuScene::uploadBatches()
{
    for (const DrawItem& item : m_layout.drawItems()) {
        if (!item.batch)
            continue;
        const BatchGeometry geometry = SceneLayout::batchGeometry(m_scene, item);
        GpuMesh g{makeVertexArray(m_gl), makeBuffer(m_gl), makeBuffer(m_gl), GLsizei(geometry.indices.size())};
        m_gl->glBindVertexArray(g.vertexArray.id());
        m_gl->glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
        m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(geometry.vertices.size() * sizeof(BatchVertex)), geometry.vertices.data(), GL_STATIC_DRAW);
        m_gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
        m_gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(geometry.indices.size() * sizeof(std::uint32_t)), geometry.indices.data(),
                           GL_STATIC_DRAW);
        setAttributes(m_gl, sizeof(BatchVertex), true);
        labelGlObject(GlLabelKind::VertexArray, g.vertexArray.id(), QStringLiteral("%1 batch %2").arg(m_scene.name).arg(m_batches.size()));
        m_batches.push_back(std::move(g));
    }
}

bool GpuScene::pose(double t)
{
    const std::vector<std::size_t> moved = m_scene.poseAt(t);
    m_layout.pose(m_scene, moved);
    return !moved.empty();
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
