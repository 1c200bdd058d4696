#include "RayTracer.h"

#include "TraceError.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

// Embree's filter for a cut-out caster, for occlusion and intersection queries alike: a hit
// where the mask is clear is not a hit.
void cutoutFilter(const RTCFilterFunctionNArguments* args)
{
    const auto* mask = static_cast<const RayTracer::CutoutMask*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1)
            continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        if (!mask->solidAt(primitive, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
    }
}

// Alpha planes of the scene's images, shared by every object that reads one.
std::shared_ptr<const std::vector<std::uint8_t>> alphaPlane(const QImage& source)
{
    const QImage image = source.convertToFormat(QImage::Format_RGBA8888);
    auto alpha = std::make_shared<std::vector<std::uint8_t>>(std::size_t(image.width()) * std::size_t(image.height()));
    for (int y = 0; y < image.height(); ++y) {
        const uchar* row = image.constScanLine(y);
        for (int x = 0; x < image.width(); ++x)
            (*alpha)[std::size_t(y) * std::size_t(image.width()) + std::size_t(x)] = row[4 * x + 3];
    }
    return alpha;
}

} // namespace

float RayTracer::CutoutMask::alphaAt(glm::vec2 uv) const
{
    // Texel centres at half-integers, wrapped as GL_REPEAT wraps each of the four texels.
    const double x = double(uv.x) * width - 0.5, y = double(uv.y) * height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const auto wrap = [](double i, int n) { return int(((long long)(i) % n + n) % n); };
    const auto at = [&](double i, double j) { return float((*alpha)[std::size_t(wrap(j, height)) * std::size_t(width) + std::size_t(wrap(i, width))]) / 255.0f; };
    const float top = float(1.0 - tx) * at(fx, fy) + float(tx) * at(fx + 1.0, fy);
    const float bottom = float(1.0 - tx) * at(fx, fy + 1.0) + float(tx) * at(fx + 1.0, fy + 1.0);
    return float(1.0 - ty) * top + float(ty) * bottom;
}

bool RayTracer::CutoutMask::solidAt(unsigned primitive, float u, float v) const
{
    if (std::size_t(primitive) * 3 + 2 >= indices.size())
        return true;
    const glm::vec2 uv = (1.0f - u - v) * uvs[indices[3 * primitive]] + u * uvs[indices[3 * primitive + 1]] + v * uvs[indices[3 * primitive + 2]];
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
        return true;
    return alphaAt(uv) >= cutoff;
}

RayTracer::RayTracer(const Scene& scene, const glm::dvec3& origin) : m_origin(origin)
{
    if (const Bounds bounds = scene.bounds(); !bounds.isEmpty()) {
        for (const glm::dvec3& corner : bounds.corners())
            m_reach = std::max(m_reach, glm::length(corner - origin));
    }
    m_device = rtcNewDevice(nullptr);
    if (!m_device)
        throw TraceError(QStringLiteral("Embree could not start (error %1)").arg(int(rtcGetDeviceError(nullptr))));
    m_scene = rtcNewScene(m_device);
    // Robust traversal: shadow rays graze triangle edges all the time (cube edges, contacts).
    rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);

    std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> alphas(scene.images.size());
    for (const SceneObject& object : scene.objects) {
        if (!object.castsShadow)
            continue;
        // Only an image's alpha varies over a surface; a cut-off above the alpha of a flat or
        // procedural texture (1) leaves nothing to trace.
        const float cutoff = textureAlphaCutoff(object);
        const bool imaged = object.texture == TextureKind::Image && object.image >= 0 && std::size_t(object.image) < scene.images.size();
        if (cutoff > 1.0f && !imaged)
            continue;
        const Mesh& mesh = scene.meshes.at(std::size_t(object.mesh));
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), mesh.vertices.size()));
        // A moving caster is its mesh in its own space, instanced where it is (pose() moves the
        // instance); a still one is baked into the scene in world space around the origin.
        const bool moving = object.motion.has_value();
        const glm::dmat4 toSpace = moving ? glm::dmat4(1.0) : glm::translate(glm::dmat4(1.0), -m_origin) * object.model;
        const glm::dmat3 linear(object.model);
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            m_reach = std::max(m_reach, glm::length(linear * glm::dvec3(mesh.vertices[i].position)));
            const glm::dvec3 world = glm::dvec3(toSpace * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0));
            vertices[3 * i + 0] = float(world.x);
            vertices[3 * i + 1] = float(world.y);
            vertices[3 * i + 2] = float(world.z);
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), mesh.indices.size() / 3));
        for (std::size_t i = 0; i < mesh.indices.size(); ++i)
            indices[i] = mesh.indices[i];
        if (cutoff > 0.0f && imaged && !scene.images[std::size_t(object.image)].isNull()) {
            if (!rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
                throw TraceError(QStringLiteral("this Embree was built without filter functions, which cut-out casters need; "
                                                "install Debian's libembree3"));
            auto& alpha = alphas[std::size_t(object.image)];
            if (!alpha)
                alpha = alphaPlane(scene.images[std::size_t(object.image)]);
            auto mask = std::make_unique<CutoutMask>();
            for (const Vertex& v : mesh.vertices)
                mask->uvs.push_back(v.uv);
            mask->indices.assign(mesh.indices.begin(), mesh.indices.end());
            mask->alpha = alpha;
            mask->width = scene.images[std::size_t(object.image)].width();
            mask->height = scene.images[std::size_t(object.image)].height();
            mask->cutoff = cutoff;
            rtcSetGeometryUserData(geometry, mask.get());
            rtcSetGeometryOccludedFilterFunction(geometry, cutoutFilter);
            rtcSetGeometryIntersectFilterFunction(geometry, cutoutFilter);
            m_masks.push_back(std::move(mask));
        }
        rtcCommitGeometry(geometry);
        if (moving)
            attachMoving(geometry, std::size_t(&object - scene.objects.data()), object.model);
        else
            rtcAttachGeometry(m_scene, geometry);
        rtcReleaseGeometry(geometry);
        m_triangles += int(mesh.indices.size() / 3);
    }
    rtcCommitScene(m_scene);
    if (const RTCError error = rtcGetDeviceError(m_device); error != RTC_ERROR_NONE)
        throw TraceError(QStringLiteral("Embree could not build the scene (error %1)").arg(int(error)));
}

void RayTracer::attachMoving(RTCGeometry geometry, std::size_t object, const glm::dmat4& model)
{
    RTCScene own = rtcNewScene(m_device);
    rtcSetSceneFlags(own, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(own, RTC_BUILD_QUALITY_HIGH);
    rtcAttachGeometry(own, geometry);
    rtcCommitScene(own);
    RTCGeometry instance = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, own);
    rtcReleaseScene(own);   // the instance holds it
    m_instances.push_back({object, instance, RTC_INVALID_GEOMETRY_ID, glm::dmat3(1.0)});
    place(m_instances.back(), model);
    m_instances.back().id = rtcAttachGeometry(m_scene, instance);
    rtcReleaseGeometry(instance);   // the scene holds it
}

void RayTracer::place(Instance& instance, const glm::dmat4& model) const
{
    instance.normalToWorld = glm::transpose(glm::inverse(glm::dmat3(model)));
    const glm::mat4 transform(glm::translate(glm::dmat4(1.0), -m_origin) * model);
    rtcSetGeometryTransform(instance.geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &transform[0][0]);
    rtcCommitGeometry(instance.geometry);
}

void RayTracer::pose(const Scene& scene)
{
    if (m_instances.empty())
        return;
    for (Instance& instance : m_instances)
        place(instance, scene.objects.at(instance.object).model);
    rtcCommitScene(m_scene);
    if (const RTCError error = rtcGetDeviceError(m_device); error != RTC_ERROR_NONE)
        throw TraceError(QStringLiteral("Embree could not move the scene's objects (error %1)").arg(int(error)));
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

// The segment o + t * direction, t in (0, tFar), around the tracer's origin.
RTCRay segment(const glm::dvec3& o, const glm::dvec3& direction, double tFar)
{
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
    return ray;
}

} // namespace

bool RayTracer::occluded(const glm::dvec3& from, const glm::dvec3& direction, double tFar) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = segment(from - m_origin, direction, tFar);
    rtcOccluded1(m_scene, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -inf.
    return ray.tfar < 0.0f;
}

} // namespace shadowlab

namespace shadowlab {

std::optional<glm::dvec3> RayTracer::casterFacetAt(const glm::dvec3& eye, const glm::dvec3& p) const
{
    const glm::dvec3 toPoint = p - eye;
    const double distance = glm::length(toPoint);
    if (!(distance > 0.0) || !std::isfinite(distance))
        return std::nullopt;
    const double tolerance = 1e-3 * distance;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = segment(eye - m_origin, toPoint / distance, distance + tolerance);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_scene, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID || std::abs(double(query.ray.tfar) - distance) > tolerance)
        return std::nullopt;
    // Embree's normal is the triangle's in the space its vertices are in: a moving caster's own.
    glm::dvec3 normal(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
    if (query.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        const auto instance = std::find_if(m_instances.begin(), m_instances.end(), [&](const Instance& i) { return i.id == query.hit.instID[0]; });
        if (instance == m_instances.end())
            return std::nullopt;
        normal = instance->normalToWorld * normal;
    }
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length))
        return std::nullopt;
    return normal / length;
}

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
