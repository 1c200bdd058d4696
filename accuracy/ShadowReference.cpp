#include "ShadowReference.h"

#include "SceneLibrary.h"
#include "ShaderConstants.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <QElapsedTimer>
#include <QThread>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <optional>

namespace shadowlab {

namespace {

// A reproducible hash (PCG output permutation) so the area reference is the same every run.
std::uint32_t hash(std::uint32_t v)
{
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

double unitFloat(std::uint32_t v)
{
    return double(v >> 8) * (1.0 / 16777216.0);
}

// Shirley-Chiu concentric map from the unit square to the unit disk: keeps strata compact.
glm::dvec2 concentricDisk(double u, double v)
{
    const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0)
        return {0.0, 0.0};
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = glm::quarter_pi<double>() * (b / a);
    } else {
        r = b;
        phi = glm::half_pi<double>() - glm::quarter_pi<double>() * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

// What every row's tracing shares: its inputs, and the buffers the rows fill, each pixel once.
struct Tracing {
    const RayTracer& tracer;
    const VisibilityBuffer& buffer;
    const LightFrame& light;
    const ReferenceOptions& options;
    int n;                          // samples per axis: n * n rays per pixel for the area reference
    glm::dvec3 u, v;                // the disk light's plane, perpendicular to the light direction
    std::vector<float>& hard;
    std::vector<float>& area;
};

// Outside a spot light's cone: unlit, nothing to trace (both buffers stay 0).
bool outsideSpotCone(const LightFrame& light, const glm::dvec3& p)
{
    if (light.spotCosine >= -1.0) {
        const glm::dvec3 fromLight = p - light.position;
        const double length = glm::length(fromLight);
        return !(length > 0.0) || glm::dot(fromLight / length, light.direction) <= light.spotCosine;
    }
    return false;
}

// A ray into the side of a surface that its geometric normal turns from crosses the surface
// itself: a caster's facet that faces away from a point of the light is in its own shadow
// there, whatever its shading normals say (near the terminator of a smooth-shaded mesh, a facet
// can face away while its normals face the light), and whatever the ray start's offset, which
// on a large model carried the ray past the facet's edge and lit it. The facet is the caster's
// triangle the camera sees at the pixel (RayTracer::casterFacetAt), asked once where a ray may
// need it, and turned to the side the pixel's normal faces: that normal, taken from the
// pixel's screen steps, rounds by a few hundredths where the camera sees the facet edge-on.
// A facet along the ray does not count (a wall under a light straight above): within
// kOwnFacetCosine, as the lit pass's OWN_FACETS. A caster the camera finds at the pixel whose
// facet leans from the pixel's normal by more than 60 degrees is another surface than the one
// measured (one that casts nothing, resting on a caster).
constexpr double kScreenNormalRounding = 0.05;
constexpr double kSameSurfaceCosine = 0.5;
struct OwnFacet {
    const RayTracer& tracer;
    glm::dvec3 eye, p, normal;
    mutable std::optional<glm::dvec3> facet;    // 0 where the pixel is on no caster

    // Whether the facet hides the light's point `direction` away from the pixel (from p).
    bool blocks(const glm::dvec3& direction) const
    {
        const double length = glm::length(direction);
        if (!(glm::dot(direction, normal) <= kScreenNormalRounding * length))
            return false;
        if (!facet) {
            const std::optional<glm::dvec3> found = tracer.casterFacetAt(eye, p);
            const double side = found ? glm::dot(*found, normal) : 0.0;
            facet = std::abs(side) < kSameSurfaceCosine ? glm::dvec3(0.0) : side < 0.0 ? -*found : *found;
        }
        return glm::dot(direction, *facet) < -double(kOwnFacetCosine) * length;
    }
};

// The share of n * n stratified points of the disk light that pixel `i`, at `from`, sees;
// `directions` is room for the rays.
float areaVisibility(const Tracing& t, int i, const glm::dvec3& from, const OwnFacet& facet, std::vector<glm::dvec3>& directions,
                     std::int64_t& rays)
{
    const int n = t.n;
    const LightFrame& light = t.light;
    for (int s = 0; s < n * n; ++s) {
        const std::uint32_t h = hash(std::uint32_t(i) * 9781u + std::uint32_t(s) * 6271u);
        const double su = (double(s % n) + unitFloat(h)) / n;
        const double sv = (double(s / n) + unitFloat(hash(h))) / n;
        const glm::dvec2 d = concentricDisk(su, sv) * t.options.lightRadius;
        const glm::dvec3 offset = t.u * d.x + t.v * d.y;
        // A directional light: of the angular size the disk has seen from the target.
        directions[std::size_t(s)] = light.perspective ? light.position + offset - from : -light.direction * light.targetDistance + offset;
    }
    // The points the facet hides are not traced: seen from the pixel itself, not from the ray's
    // start off the surface.
    const glm::dvec3 fromPixel = from - facet.p;
    const auto traced = std::partition(directions.begin(), directions.begin() + n * n,
                                       [&](const glm::dvec3& d) { return !facet.blocks(d + fromPixel); });
    const int count = int(traced - directions.begin());
    const int unoccluded = count - t.tracer.occludedCount(from, directions.data(), count, light.perspective ? 1.0 : 1e30);
    rays += count;
    return float(unoccluded) / float(n * n);
}

} // namespace

glm::dvec3 shadowRayStart(const RayTracer& tracer, const glm::dvec3& p, const glm::dvec3& normal)
{
    // The floor of 1 unit alone moved the rays off a sphere of radius 0.017 by 1.2 % of its
    // radius, past the facets that shadow its terminator; a hundredth of the reach keeps 100
    // times the rounding of the coordinates there (RayTracer::reach).
    const double floor = std::min(1.0, 0.01 * tracer.reach());
    return p + normal * (2e-4 * std::max(floor, glm::length(p - tracer.origin())));
}

namespace {

// Traces every pixel of row `y` that faces the light; returns the rays it took.
std::int64_t traceRow(const Tracing& t, int y)
{
    const int width = t.buffer.size.width(), n = t.n;
    const LightFrame& light = t.light;
    std::int64_t rays = 0;
    std::vector<glm::dvec3> directions(t.options.area ? std::size_t(n * n) : 0);
    for (int x = 0; x < width; ++x) {
        const int i = y * width + x;
        if (t.buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const glm::dvec3 p = t.buffer.worldPosition(i);
        const glm::dvec3 normal = t.buffer.normal(i);
        const glm::dvec3 from = shadowRayStart(t.tracer, p, normal);
        if (outsideSpotCone(light, p))
            continue;
        const OwnFacet facet{t.tracer, t.buffer.cameraPosition, p, normal, std::nullopt};
        if (facet.blocks(light.perspective ? light.position - p : -light.direction)) {
            t.hard[std::size_t(i)] = 0.0f;
        } else {
            if (light.perspective)
                t.hard[std::size_t(i)] = t.tracer.occluded(from, light.position - from, 1.0) ? 0.0f : 1.0f;
            else
                t.hard[std::size_t(i)] = t.tracer.occluded(from, -light.direction, 1e30) ? 0.0f : 1.0f;
            ++rays;
        }
        if (t.options.area)
            t.area[std::size_t(i)] = areaVisibility(t, i, from, facet, directions, rays);
    }
    return rays;
}

// The mean standard error of the area estimate over the pixels that face the light.
double areaNoiseFloor(const VisibilityBuffer& buffer, const ReferenceVisibility& result)
{
    double sum = 0.0;
    int counted = 0;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const double a = result.area[std::size_t(i)];
        sum += std::sqrt(a * (1.0 - a) / result.samplesPerPixel);
        ++counted;
    }
    return counted ? sum / counted : 0.0;
}

} // namespace

ReferenceKey referenceKeyFor(const Settings& settings, QSize size, int samplesPerAxis)
{
    return {sceneIdentity(settings.scene), settings.camera, size,
            settings.light.position, settings.light.target,  settings.light.projection,
            settings.light.type, settings.light.type == LightType::Spot ? settings.light.fov : 0.0,
            settings.reference.lightRadius, samplesPerAxis, settings.objects,
            sceneMoves(settings.scene) ? settings.animation.time : 0.0};
}

ReferenceVisibility traceReference(const RayTracer& tracer, const VisibilityBuffer& buffer, const LightFrame& light,
                                   const ReferenceOptions& options, const std::function<void(double)>& progress,
                                   const std::atomic<bool>* cancel)
{
    QElapsedTimer timer;
    timer.start();
    const int height = buffer.size.height();
    const int n = std::max(1, options.samplesPerAxis);
    ReferenceVisibility result;
    result.hard.assign(std::size_t(buffer.pixelCount()), 0.0f);
    if (options.area) {
        result.area.assign(std::size_t(buffer.pixelCount()), 0.0f);
        result.samplesPerPixel = n * n;
    }

    // The disk light's frame: perpendicular to the light direction.
    const glm::dvec3 w = light.direction;
    const glm::dvec3 helper = std::abs(w.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, w));
    const Tracing tracing{tracer, buffer, light, options, n, u, glm::cross(w, u), result.hard, result.area};

    std::vector<int> rows(static_cast<std::size_t>(height));
    std::iota(rows.begin(), rows.end(), 0);
    std::atomic<std::int64_t> rays{0};
    std::atomic<int> rowsDone{0};
    QFuture<void> future = QtConcurrent::map(rows, [&](int y) {
        if (cancel && cancel->load())
            return;
        rays += traceRow(tracing, y);
        ++rowsDone;
    });
    while (!future.isFinished()) {
        if (progress)
            progress(double(rowsDone.load()) / height);
        QThread::msleep(50);
    }
    future.waitForFinished();
    result.cancelled = cancel && cancel->load();
    if (progress && !result.cancelled)
        progress(1.0);

    if (options.area)
        result.areaNoiseFloor = areaNoiseFloor(buffer, result);
    result.rays = rays.load();
    result.seconds = double(timer.nsecsElapsed()) * 1e-9;
    return result;
}

} // namespace shadowlab
