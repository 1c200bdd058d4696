#pragma once

#include "GlObject.h"
#include "Scene.h"

#include <array>
#include <optional>
#include <vector>

namespace shadowlab {

// A Scene uploaded to one context: a vertex array per mesh (VAOs are per context), a mipmapped
// texture per procedural TextureKind, a white one for flat colours and one per scene image.
// Attribute locations: 0 position, 1 normal, 2 uv.
class GpuScene {
public:
    GpuScene(GlFunctions* gl, Scene scene);

    const Scene& scene() const { return m_scene; }
    // World bounds of scene().objects[i], computed once at upload (culling runs per frame).
    const Bounds& objectBounds(std::size_t i) const { return m_objectBounds.at(i); }
    // scene().bounds(), computed once: Scene::bounds() visits every vertex.
    const Bounds& bounds() const { return m_bounds; }
    // flatPlane() of scene().meshes[mesh], computed once at upload.
    const std::optional<MeshPlane>& meshPlane(int mesh) const { return m_meshPlanes.at(std::size_t(mesh)); }
    // Binds the object's vertex array and draws it.
    void draw(const SceneObject& object) const;
    // The diffuse texture the object's colour is multiplied by (its base colour multiplies it).
    GLuint texture(const SceneObject& object) const;

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
    std::vector<std::optional<MeshPlane>> m_meshPlanes;
    Bounds m_bounds;
    std::array<GlTexture, 3> m_textures;   // Checker, Wood, Flat (white)
    std::vector<GlTexture> m_images;
};

} // namespace shadowlab
