#pragma once

#include "GlObject.h"
#include "Scene.h"
#include "SceneLayout.h"

#include <QOpenGLFunctions>

#include <array>
#include <optional>
#include <vector>

namespace shadowlab {

// A Scene uploaded to one context: a vertex array per mesh (VAOs are per context), a mipmapped
// texture per procedural TextureKind, a white one for flat colours and one per scene image.
// Attribute locations: 0 position, 1 normal, 2 uv, 3 base colour (a constant but in batches).
// Its draw items and batches are its SceneLayout's.
class GpuScene {
public:
    GpuScene(GlFunctions* gl, Scene scene);

    // The scene, its moving objects where the last pose() put them.
    const Scene& scene() const { return m_scene; }
    // Places the moving objects where they are at time `t` seconds: whether any moved. A still
    // scene does nothing. Only transforms change; nothing is uploaded again.
    bool pose(double t);
    // The scene's bounds, draw items and planes, computed once at upload.
    const SceneLayout& layout() const { return m_layout; }
    const Bounds& bounds() const { return m_layout.bounds(); }
    // What the passes draw: every object once, alone or in a batch.
    const std::vector<DrawItem>& drawItems() const { return m_layout.drawItems(); }
    // scene().hasCutouts(), found once at upload (the lit pass asks every frame).
    bool hasCutouts() const { return m_hasCutouts; }
    // Whether a caster is smooth-shaded (DrawItem::smoothShaded): the lit pass's lookups then
    // shadow a caster's facets that face away from the light (OWN_FACETS).
    bool hasSmoothCasters() const { return m_hasSmoothCasters; }
    // Binds the item's vertex array and draws it; with `colour`, an object's base colour is set
    // as the constant of attribute 3 (the passes that read positions only leave it alone).
    void draw(const DrawItem& item, bool colour = true) const;
    // The diffuse texture the object's colour is multiplied by (its base colour multiplies it).
    GLuint texture(const SceneObject& object) const;
    GLuint texture(const DrawItem& item) const { return texture(m_scene.objects.at(item.objects.front())); }

private:
    void uploadBatches();

    struct GpuMesh {
        GlVertexArray vertexArray;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei indexCount = 0;
    };

    GlFunctions* m_gl;
    QOpenGLFunctions* m_es;     // the context's: glVertexAttrib3f, which the 3.3 core set leaves out
    Scene m_scene;
    SceneLayout m_layout;
    std::vector<GpuMesh> m_meshes;
    std::vector<GpuMesh> m_batches;         // the vertex arrays of the batched items, in order
    bool m_hasCutouts = false;
    bool m_hasSmoothCasters = false;
    std::array<GlTexture, 3> m_textures;   // Checker, Wood, Flat (white)
    std::vector<GlTexture> m_images;
};

} // namespace shadowlab
