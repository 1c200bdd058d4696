#pragma once

#include "Scene.h"

#include <glm/vec3.hpp>

#include <embree3/rtcore.h>

namespace shadowlab {

// Embree occlusion queries against a Scene's shadow casters, in world space. Geometry is
// stored relative to `origin` (pick the camera position) so float precision holds near what
// is measured even when the scene sits far from the world origin. Queries are thread-safe.
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

    const glm::dvec3& origin() const { return m_origin; }
    int triangleCount() const { return m_triangles; }

private:
    glm::dvec3 m_origin;
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
    int m_triangles = 0;
};

} // namespace shadowlab
