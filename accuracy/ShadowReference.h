#pragma once

#include "LightMath.h"
#include "RayTracer.h"
#include "Settings.h"
#include "VisibilityBuffer.h"

#include <QSize>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace shadowlab {

// Ray-traced light visibility at exactly the world positions the rasteriser produced.
struct ReferenceVisibility {
    std::vector<float> hard;        // one shadow ray per pixel toward the light (point or direction), none behind its own facet
    std::vector<float> area;        // fraction of unoccluded stratified samples of a disk light; empty if not asked
    int samplesPerPixel = 0;        // of the area reference
    double areaNoiseFloor = 0.0;    // mean standard error of the area estimate over measured pixels
    std::int64_t rays = 0;
    double seconds = 0.0;
    bool cancelled = false;         // stopped early through `cancel`: the buffers are incomplete
    double raysPerSecond() const { return seconds > 0.0 ? double(rays) / seconds : 0.0; }
};

// What a reference depends on: scene, camera, image size and the light's placement and size.
// Map size, bias and filter do not change it, so every configuration that shares a key can
// share one trace.
struct ReferenceKey {
    QString scene;                  // sceneIdentity(): a preset's name or a hash of a file's content
    CameraSettings camera;
    QSize size;
    glm::dvec3 lightPosition{0.0};
    glm::dvec3 lightTarget{0.0};
    LightProjection projection = LightProjection::Ortho;
    LightType type = LightType::Directional;
    double coneFov = 0.0;           // a spot light's cone
    double lightRadius = 0.0;
    int samplesPerAxis = 0;
    ObjectSwitches objects;         // casters and receivers switched off change what is traced
    double time = 0.0;              // scene.time where the scene moves (0 where it is still)

    bool operator==(const ReferenceKey&) const = default;
};

ReferenceKey referenceKeyFor(const Settings& settings, QSize size, int samplesPerAxis);

struct ReferenceOptions {
    bool area = true;
    double lightRadius = 0.25;      // world units
    int samplesPerAxis = 16;        // the area reference traces samplesPerAxis^2 rays per pixel
};

// Where a shadow ray from surface point `p`, of geometric normal `normal`, starts: off the
// surface along the normal by 2e-4 of the point's distance from the tracer's origin, and at
// least of 1 unit, or of a hundredth of the tracer's reach where that is less (a model a few
// centimetres across is traced as one a few metres across), so float rounding cannot put it
// behind the surface.
glm::dvec3 shadowRayStart(const RayTracer& tracer, const glm::dvec3& p, const glm::dvec3& normal);

// Visibility of the light for every pixel of `buffer` that faces it (others stay 0). Rays
// start a small distance off the surface along the geometric normal; one toward a point of the
// light behind the pixel's own facet, on a caster, is blocked without being traced (near the
// terminator of a smooth-shaded mesh a facet faces away while its normals face the light,
// ShadowReference.cpp's OwnFacet). Directional (ortho)
// lights trace parallel rays, and for the area reference a disk of the light's angular size
// seen from its target; perspective lights trace to the light's position and to a disk there,
// facing along the light direction; a spot light's receivers outside its cone (light.fov,
// LightFrame::spotCosine) are unlit, and a point light's rays go every way. Runs on every core (Qt's global thread pool);
// `progress` (0..1) is called from the calling thread between rows; setting `*cancel` stops
// the work early. Needs no GL context, so it can run off the GUI thread.
ReferenceVisibility traceReference(const RayTracer& tracer, const VisibilityBuffer& buffer, const LightFrame& light,
                                   const ReferenceOptions& options, const std::function<void(double)>& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);

} // namespace shadowlab
