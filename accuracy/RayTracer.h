#pragma once

#include "Scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace shadowlab {

// Embree occlusion queries against a Scene's shadow casters, in world space. Geometry is
// stored relative to `origin` (pick the camera position) so float precision holds near what
// is measured even when the scene sits far from the world origin. Queries are thread-safe.
// Moving casters (SceneObject::motion) are instances of their meshes: pose() moves them to
// another instant and commits the scene again, without building it anew.
// Cut-out casters (SceneObject::alphaCutoff) are traced through their holes: an occlusion filter
// reads the texture's alpha at the hit, bilinear at full resolution as the shadow pass reads it.
class RayTracer {
public:
    RayTracer(const Scene& scene, const glm::dvec3& origin);
    ~RayTracer();
    RayTracer(const RayTracer&) = delete;
    RayTracer& operator=(const RayTracer&) = delete;

    // Is anything hit on the segment origin + t * direction, t in (0, tFar)? World coordinates.
    bool occluded(const glm::dvec3& from, const glm::dvec3& direction, double tFar) const;
    // How many of the `count` segments from + t * directions[i], t in (0, tFar), hit anything:
    // occluded() for each, traced 16 at a time, as rays from one point toward one light share
    // most of their way through the scene.
    int occludedCount(const glm::dvec3& from, const glm::dvec3* directions, int count, double tFar) const;

    // The unit normal (either side) of the caster's triangle that the camera at `eye` sees at
    // `p`, in world space: where the first thing its ray meets lies within a thousandth of the
    // distance to p. Nullopt elsewhere: a surface that casts no shadow is not traced, so the ray
    // meets something farther, or nothing.
    std::optional<glm::dvec3> casterFacetAt(const glm::dvec3& eye, const glm::dvec3& p) const;

    // The moving casters placed as `scene`'s models say (the scene this tracer was made from,
    // posed at another time: Scene::poseAt). Not thread-safe against queries.
    void pose(const Scene& scene);
    // How many casters move (are instanced).
    int movingCasterCount() const { return int(m_instances.size()); }

    const glm::dvec3& origin() const { return m_origin; }
    // The scale of the coordinates a surface point of the scene carries: how far the scene
    // reaches from the origin (the farthest corner of its bounds), or a mesh from its own
    // object's origin where that is more. A float coordinate of the traced triangles, or of a
    // point the GPU placed on them, rounds by about 1e-7 of it.
    double reach() const { return m_reach; }
    int triangleCount() const { return m_triangles; }
    // Casters traced through a mask (cut-outs whose texture has an alpha that can fall below
    // the cut-off).
    int maskedCasterCount() const { return int(m_masks.size()); }

    // What the occlusion filter of one cut-out caster reads: its triangles' texture coordinates
    // and its texture's alpha, 0..255, rows from the top as uploaded.
    struct CutoutMask {
        std::vector<glm::vec2> uvs;         // per vertex
        std::vector<unsigned> indices;      // three per triangle
        std::shared_ptr<const std::vector<std::uint8_t>> alpha;
        int width = 0;
        int height = 0;
        float cutoff = 0.0f;                // textureAlphaCutoff(), on alpha in 0..1

        // The texture's alpha at `uv`, bilinear with repeat, as GL samples level 0.
        float alphaAt(glm::vec2 uv) const;
        // Whether the surface is there at barycentric (u, v) of triangle `primitive`.
        bool solidAt(unsigned primitive, float u, float v) const;
    };

private:
    struct Instance {
        std::size_t object = 0;     // index into the scene's objects
        RTCGeometry geometry = nullptr;     // owned by the scene it is attached to
        unsigned id = RTC_INVALID_GEOMETRY_ID;  // its ID in the tracer's scene
        glm::dmat3 normalToWorld{1.0};      // where pose() put it
    };
    // `geometry` (a moving caster's mesh in its own space) in a scene of its own, instanced
    // into the tracer's at `model`.
    void attachMoving(RTCGeometry geometry, std::size_t object, const glm::dmat4& model);
    void place(Instance& instance, const glm::dmat4& model) const;

    glm::dvec3 m_origin;
    double m_reach = 0.0;
    std::vector<Instance> m_instances;
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
    int m_triangles = 0;
    std::vector<std::unique_ptr<CutoutMask>> m_masks;   // each one geometry's filter data
};

} // namespace shadowlab
