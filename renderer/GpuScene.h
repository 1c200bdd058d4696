#pragma once

#include "GlObject.h"
#include "Scene.h"

#include <array>
#include <vector>

namespace shadowlab {

// A Scene uploaded to one context: a vertex array per mesh (VAOs are per context) and a
// mipmapped texture per TextureKind. Attribute locations: 0 position, 1 normal, 2 uv.
class GpuScene {
public:
    GpuScene(GlFunctions* gl, Scene scene);

    const Scene& scene() const { return m_scene; }
    // World bounds of scene().objects[i], computed once at upload (culling runs per frame).
    const Bounds& objectBounds(std::size_t i) const { return m_objectBounds.at(i); }
    // Binds the object's vertex array and draws it.
    void draw(const SceneObject& object) const;
    GLuint texture(TextureKind kind) const { return m_textures[std::size_t(kind)].id(); }

private:
    struct GpuMesh {
        GlVertexArray vertexArray;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei indexCount = 0;
    };

    GlFunctions* m_gl;
    Scene m_scene;
    std::vector<GpuMesh> m_meshes;
    std::vector<Bounds> m_objectBounds;
    std::array<GlTexture, 2> m_textures;
};

} // namespace shadowlab
