#pragma once

#include "LightMath.h"
#include "Scene.h"
#include "ShadowReach.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
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
    bool moves = false;                 // a moving object's (drawn alone): a dynamic caster to a cache
    // A cut-out's texture alpha below which it is not there (textureAlphaCutoff); 0: opaque.
    // Items that honour a mask draw with their pass's ALPHA_CUTOUT variant (shaders/cutout.glsl).
    float alphaCutoff = 0.0f;
    int mesh = 0;                       // an object's mesh; a batch's index among the batches otherwise
    // A floor: a flat object with every other object on the side its plane faces (a model's
    // ground). A light on that side sees nothing through it, so it shadows nothing there and the
    // shadow passes leave it out: exact, and the floor cannot shadow itself (no acne, no moiré
    // of a wide filter's taps on it), whatever the bias.
    std::optional<WorldPlane> floor;
    // Its mesh, or one of a batch's, is smooth-shaded (smoothShaded(Mesh)): its facets can face
    // away from the light where its normals face it, and a caster's are then in its own shadow.
    bool smoothShaded = false;
};

// Which casters a shadow pass draws: all, or for a cache (renderer/ShadowCache.h) the still
// ones into its copy and the moving ones over it.
enum class CasterSet { All, Still, Moving };
inline bool drawsItem(CasterSet set, const DrawItem& item)
{
    return set == CasterSet::All || (set == CasterSet::Moving) == item.moves;
}

// Whether `item` can shadow nothing under `light`: a floor with the light on its front side.
bool shadowsNothing(const DrawItem& item, const LightFrame& light);

// A batch's merged geometry: its members' vertices in world space around the batch's centre,
// each with its object's base colour (a vertex first, so the attributes of both lie alike).
struct BatchVertex {
    Vertex vertex;
    glm::vec3 colour;
};
struct BatchGeometry {
    std::vector<BatchVertex> vertices;
    std::vector<std::uint32_t> indices;
};

// The CPU side of a scene as the frame uses it, computed once: each object's world bounds, each
// mesh's plane, and the draw items, every object once, alone or in a batch. Scenes of many
// objects are drawn in batches: a fixed grid of cells over the scene, one batch per cell and
// material, so that draw calls do not grow with the objects. No GL: the fit, the reach and the
// passes' culling read it, GpuScene uploads what it lays out, and it is tested without a context.
class SceneLayout {
public:
    explicit SceneLayout(const Scene& scene);

    // Places the objects `moved` (indices) where `scene`'s models now put them: their bounds,
    // boxes and draw items. `scene` is the one this layout was made from, posed (Scene::poseAt).
    // A moving object is drawn alone and is never a floor, so nothing else changes.
    void pose(const Scene& scene, const std::vector<std::size_t>& moved);
    // Whether scene.objects[i] moves.
    bool moves(std::size_t i) const { return m_swept.at(i).has_value(); }
    // The indices of the objects that move, in order.
    const std::vector<std::size_t>& movingObjects() const { return m_moving; }

    // What the light is fitted to for scene.objects[i]: everywhere it goes, for one that moves,
    // so the map's volume and texel grid stand still while it moves (no swimming).
    const Bounds& fitBounds(std::size_t i) const { return m_swept.at(i) ? *m_swept[i] : m_objectBounds.at(i); }
    // World bounds of scene.objects[i] as posed (culling runs per frame).
    const Bounds& objectBounds(std::size_t i) const { return m_objectBounds.at(i); }
    // The corners of scene.objects[i]'s mesh's own box through its model (as Bounds::corners()):
    // tighter than objectBounds where the object turns.
    std::array<glm::dvec3, 8> objectBox(std::size_t i) const;
    // The scene's bounds, with everywhere its moving objects go: Scene::bounds() visits every vertex.
    const Bounds& bounds() const { return m_bounds; }
    // The world plane scene.objects[i] lies in, if its mesh is flat.
    std::optional<WorldPlane> objectPlane(std::size_t i) const;
    // Whether scene.objects[i] is a floor (DrawItem::floor).
    bool isFloor(std::size_t i) const { return m_objectFloors.at(i).has_value(); }
    const std::vector<DrawItem>& drawItems() const { return m_items; }
    // The batched items, in the order of their DrawItem::mesh.
    int batchCount() const { return m_batchCount; }
    // The merged vertices of a batched item of `scene` (the one this layout was made from).
    static BatchGeometry batchGeometry(const Scene& scene, const DrawItem& item);

private:
    void layOutItems(const Scene& scene);
    std::optional<WorldPlane> floorPlane(std::size_t i) const;

    std::vector<Bounds> m_objectBounds;
    std::vector<Bounds> m_meshBounds;           // each mesh's, in its own space
    std::vector<glm::dmat4> m_objectModels;
    std::vector<int> m_objectMeshes;
    std::vector<std::optional<MeshPlane>> m_meshPlanes;
    std::vector<bool> m_meshSmooth;             // smoothShaded(), per mesh
    std::vector<std::optional<WorldPlane>> m_objectFloors;     // each object's plane, where it is a floor
    std::vector<std::optional<Bounds>> m_swept;                // where each moving object goes
    std::vector<std::size_t> m_moving;                         // the objects that do
    std::vector<std::optional<Bounds>> m_sampled;              // ... at the sweep's samples (the floor test)
    std::vector<std::size_t> m_itemOf;                         // each object's draw item
    std::vector<DrawItem> m_items;
    Bounds m_bounds;
    int m_batchCount = 0;
};

} // namespace shadowlab
