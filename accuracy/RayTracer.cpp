#include "RayTracer.h"

#include "TraceError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace shadowlab {

RayTracer::RayTracer(const Scene& scene, const glm::dvec3& origin) : m_origin(origin)
{
    m_device = rtcNewDevice(nullptr);
    if (!m_device)
        throw TraceError(QStringLiteral("Embree could not start (error %1)").arg(int(rtcGetDeviceError(nullptr))));
    m_scene = rtcNewScene(m_device);
    // Robust traversal: shadow rays graze triangle edges all the time (cube edges, contacts).
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);

    for (const SceneObject& object : scene.objects) {
        if (!object.castsShadow)
            continue;
        const Mesh& mesh = scene.meshes.at(std::size_t(object.mesh));
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), mesh.vertices.size()));
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            const glm::dvec3 world = glm::dvec3(object.model * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0)) - m_origin;
            vertices[3 * i + 0] = float(world.x);
            vertices[3 * i + 1] = float(world.y);
            vertices[3 * i + 2] = float(world.z);
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), mesh.indices.size() / 3));
        for (std::size_t i = 0; i < mesh.indices.size(); ++i)
            indices[i] = mesh.indices[i];
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(m_scene, geometry);
        rtcReleaseGeometry(geometry);
        m_triangles += int(mesh.indices.size() / 3);
    }
    rtcCommitScene(m_scene);
    if (const RTCError error = rtcGetDeviceError(m_device); error != RTC_ERROR_NONE)
        throw TraceError(QStringLiteral("Embree could not build the scene (error %1)").arg(int(error)));
}

RayTracer::~RayTracer()
{
    if (m_scene)
        rtcReleaseScene(m_scene);
    if (m_device)
        rtcReleaseDevice(m_device);
}

namespace {

float farLimit(double tFar)
{
    return tFar < double(std::numeric_limits<float>::max()) ? float(tFar) : std::numeric_limits<float>::infinity();
}

} // namespace

bool RayTracer::occluded(const glm::dvec3& from, const glm::dvec3& direction, double tFar) const
{
    const glm::dvec3 o = from - m_origin;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = float(o.x);
    ray.org_y = float(o.y);
    ray.org_z = float(o.z);
    ray.dir_x = float(direction.x);
    ray.dir_y = float(direction.y);
    ray.dir_z = float(direction.z);
    ray.tnear = 0.0f;
    ray.tfar = farLimit(tFar);
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(m_scene, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -inf.
    return ray.tfar < 0.0f;
}

} // namespace shadowlab

namespace shadowlab {

int RayTracer::occludedCount(const glm::dvec3& from, const glm::dvec3* directions, int count, double tFar) const
{
    constexpr int kLanes = 16;
    const glm::dvec3 o = from - m_origin;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    int blocked = 0;
    for (int first = 0; first < count; first += kLanes) {
        alignas(64) RTCRay16 rays{};
        alignas(64) int valid[kLanes];
        const int lanes = std::min(kLanes, count - first);
        for (int k = 0; k < kLanes; ++k) {
            valid[k] = k < lanes ? -1 : 0;
            if (k >= lanes)
                continue;
            const glm::dvec3& d = directions[first + k];
            rays.org_x[k] = float(o.x);
            rays.org_y[k] = float(o.y);
            rays.org_z[k] = float(o.z);
            rays.dir_x[k] = float(d.x);
            rays.dir_y[k] = float(d.y);
            rays.dir_z[k] = float(d.z);
            rays.tnear[k] = 0.0f;
            rays.tfar[k] = farLimit(tFar);
            rays.mask[k] = 0xFFFFFFFFu;
        }
        rtcOccluded16(valid, m_scene, &context, &rays);
        for (int k = 0; k < lanes; ++k)
            blocked += rays.tfar[k] < 0.0f;
    }
    return blocked;
}

} // namespace shadowlab
