#pragma once

#include "GlObject.h"
#include "Scene.h"

#include <QOpenGLFunctions>

#include <array>
#include <optional>
#include <vector>

namespace shadowlab {

// What one draw call draws: a scene object, or a batch of small objects that share a texture,
// shadow flags and alpha cut-off, merged into one vertex buffer in world space around the batch's centre
// (so float keeps the precision of a scene far from the origin), its base colours per vertex.
struct DrawItem {
    std::vector<std::size_t> objects;   // indices into scene().objects
    Bounds bounds;                      // world
    glm::dmat4 model{1.0};              // the item's vertices to world
    glm::dmat3 normalMatrix{1.0};
    glm::vec3 baseColour{1.0f};         // an object's; a batch's colours are on its vertices
    bool castsShadow = true;
    bool receivesShadow = true;
    bool batch = false;
    // A cut-out's texture alpha below which it is not there (textureAlphaCutoff); 0: opaque.
    // Items that honour a mask draw with their pass's ALPHA_CUTOUT variant (shaders/cutout.glsl).
    float alphaCutoff = 0.0f;
    int mesh = 0;                       // an object's mesh; a batch's own vertex array otherwise
};

// A Scene uploaded to one context: a vertex array per mesh (VAOs are per context), a mipmapped
// texture per procedural TextureKind, a white one for flat colours and one per scene image.
// Attribute locations: 0 position, 1 normal, 2 uv, 3 base colour (a constant but in batches).
// Scenes of many objects are drawn in batches: a fixed grid of cells over the scene, one
// batch per cell and material, so that draw calls do not grow with the objects.
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
    // What the passes draw: every object once, alone or in a batch.
    const std::vector<DrawItem>& drawItems() const { return m_items; }
    // scene().hasCutouts(), found once at upload (the lit pass asks every frame).
    bool hasCutouts() const { return m_hasCutouts; }
    // Binds the item's vertex array and draws it; with `colour`, an object's base colour is set
    // as the constant of attribute 3 (the passes that read positions only leave it alone).
    void draw(const DrawItem& item, bool colour = true) const;
    // The diffuse texture the object's colour is multiplied by (its base colour multiplies it).
    GLuint texture(const SceneObject& object) const;
    GLuint texture(const DrawItem& item) const { return texture(m_scene.objects.at(item.objects.front())); }

private:
    void buildDrawItems();

    struct GpuMesh {
        GlVertexArray vertexArray;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei indexCount = 0;
    };

    GlFunctions* m_gl;
    QOpenGLFunctions* m_es;     // the context's: glVertexAttrib3f, which the 3.3 core set leaves out
    Scene m_scene;
    std::vector<GpuMesh> m_meshes;
    std::vector<Bounds> m_objectBounds;
    std::vector<std::optional<MeshPlane>> m_meshPlanes;
    std::vector<DrawItem> m_items;
    std::vector<GpuMesh> m_batches;         // the vertex arrays of the batched items, in order
    Bounds m_bounds;
    bool m_hasCutouts = false;
    std::array<GlTexture, 3> m_textures;   // Checker, Wood, Flat (white)
    std::vector<GlTexture> m_images;
};

} // namespace shadowlab
