#pragma once

#include "RayTracer.h"
#include "Renderer.h"
#include "SceneSupply.h"
#include "ShadowReference.h"

#include <glm/glm.hpp>

#include <QSize>
#include <QString>

#include <cmath>
#include <vector>

// How a rendered shadow term agrees with the Embree hard reference at exactly the rendered
// pixels: what GL tests assert when they say "the shadows are where the ray tracer says".
namespace probe {

// Over the receivers facing the light: the reference's shadowed pixels and both kinds of
// misclassified pixel.
struct Agreement {
    int counted = 0;
    int referenceShadowed = 0;
    int falseShadow = 0;
    int falseLight = 0;
    int falseLightUncovered = 0;    // of those, outside the light's volume (lit without a test)
};

// The hard reference at the pixels of `buffer`, which `renderer` drew last.
inline std::vector<float> hardReference(shadowlab::Renderer& renderer, const shadowlab::VisibilityBuffer& buffer)
{
    using namespace shadowlab;
    const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
    ReferenceOptions options;
    options.area = false;
    return traceReference(tracer, buffer, renderer.lightFrame(), options).hard;
}

// `buffer` against the hard reference `expected` of its pixels, `light` the frame it was drawn with.
inline Agreement agreement(const shadowlab::VisibilityBuffer& buffer, const std::vector<float>& hard, const shadowlab::LightFrame& light)
{
    using namespace shadowlab;
    Agreement a;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const float measured = buffer.visibility(i);
        const float expected = hard[std::size_t(i)];
        ++a.counted;
        a.referenceShadowed += expected < 0.5f;
        a.falseShadow += measured < expected - 0.5f;
        if (measured > expected + 0.5f) {
            ++a.falseLight;
            const glm::dvec4 t = light.shadowMatrix * glm::dvec4(buffer.worldPosition(i), 1.0);
            const glm::dvec3 p = glm::dvec3(t) / t.w;
            a.falseLightUncovered += t.w <= 0.0 || glm::any(glm::lessThan(p, glm::dvec3(0.0))) || glm::any(glm::greaterThan(p, glm::dvec3(1.0)));
        }
    }
    return a;
}

// The measuring frame of `settings`, its scene handed to the renderer first where it is a file
// (as the command line and the window hand theirs).
inline shadowlab::VisibilityBuffer visibility(shadowlab::Renderer& renderer, const shadowlab::Settings& settings, QSize size)
{
    shadowlab::supplyScene(renderer, settings);
    return renderer.renderVisibility(settings, size);
}

inline Agreement agreement(shadowlab::Renderer& renderer, const shadowlab::Settings& settings, QSize size)
{
    const shadowlab::VisibilityBuffer buffer = visibility(renderer, settings, size);
    return agreement(buffer, hardReference(renderer, buffer), renderer.lightFrame());
}

// The counts of `a` in words, for a test's failure message and log.
inline QString describe(const Agreement& a)
{
    return QString("%1 counted, %2 shadowed in the reference, %3 false shadow, %4 false light")
        .arg(a.counted).arg(a.referenceShadowed).arg(a.falseShadow).arg(a.falseLight);
}

// A unit vector toward the light from azimuth (from +x toward +z) and elevation (above the
// ground plane), in degrees: the light placements the reference tests sweep.
inline glm::dvec3 fromAngles(double azimuthDegrees, double elevationDegrees)
{
    const double az = glm::radians(azimuthDegrees), el = glm::radians(elevationDegrees);
    return {std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
}

} // namespace probe
