#include "AccuracyMeter.h"

#include <glm/common.hpp>

#include <algorithm>

namespace shadowlab {

AccuracyMeter::AccuracyMeter(ReferenceOptions options) : m_options(options) {}

GreyImage shadedLuma(const VisibilityBuffer& buffer, const std::vector<float>& visibility)
{
    GreyImage image{buffer.size.width(), buffer.size.height(), std::vector<float>(std::size_t(buffer.pixelCount()), 0.0f)};
    const std::size_t n = std::min({image.values.size(), visibility.size(), buffer.ambientLight.size(), buffer.directLight.size()});
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 lit = glm::dvec3(buffer.ambientLight[i]) + double(visibility[i]) * glm::dvec3(buffer.directLight[i]);
        const glm::dvec3 shown = glm::clamp(lit, 0.0, 1.0);
        image.values[i] = float(0.299 * shown.r + 0.587 * shown.g + 0.114 * shown.b);
    }
    return image;
}

AccuracyResult compareWithReference(const VisibilityBuffer& buffer, const ReferenceVisibility& reference)
{
    std::vector<bool> counts(std::size_t(buffer.pixelCount()));
    std::vector<float> measured(counts.size());
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        counts[std::size_t(i)] = buffer.mask(i) == VisibilityBuffer::FacingLight;
        measured[std::size_t(i)] = buffer.visibility(i);
    }
    AccuracyResult result;
    result.hard = compareVisibility(measured, reference.hard, counts);
    if (!reference.area.empty())
        result.area = compareVisibility(measured, reference.area, counts);
    // Shaded with the reference where it was traced (light-facing pixels), as measured elsewhere.
    std::vector<float> referenceShade = measured;
    for (std::size_t i = 0; i < counts.size() && i < reference.hard.size(); ++i) {
        if (counts[i])
            referenceShade[i] = reference.hard[i];
    }
    const GreyImage shown = shadedLuma(buffer, measured);
    result.ssim = meanSsim(shown, shadedLuma(buffer, referenceShade));
    if (!reference.area.empty()) {
        for (std::size_t i = 0; i < counts.size() && i < reference.area.size(); ++i) {
            if (counts[i])
                referenceShade[i] = reference.area[i];
        }
        result.areaSsim = meanSsim(shown, shadedLuma(buffer, referenceShade));
    }
    result.areaNoiseFloor = reference.areaNoiseFloor;
    result.frame = buffer.image;
    result.hardErrors = errorImage(buffer.image, measured, reference.hard, counts);
    result.hardHeat = errorHeatImage(buffer.image, measured, reference.hard, counts);
    return result;
}

const RayTracer& AccuracyMeter::tracerFor(const Scene& scene, const glm::dvec3& origin)
{
    TracedScene traced{scene.name, scene.identity, origin, scene.meshes.size(), {}};
    for (const SceneObject& object : scene.objects)
        traced.casts.push_back(object.castsShadow);
    if (m_tracer && m_traced == traced) {
        m_tracer->pose(scene);
        return *m_tracer;
    }
    m_tracer.reset();   // one Embree scene at a time
    m_tracer = std::make_unique<RayTracer>(scene, origin);
    m_traced = std::move(traced);
    return *m_tracer;
}

AccuracyResult AccuracyMeter::measure(const VisibilityBuffer& buffer, const Scene& scene, const LightFrame& light,
                                      const Settings& settings, const std::function<void(double)>& progress)
{
    const ReferenceKey key = referenceKeyFor(settings, buffer.size, m_options.area ? m_options.samplesPerAxis : 0);
    auto cached = std::find_if(m_references.begin(), m_references.end(), [&](const auto& entry) { return entry.first == key; });
    const bool reused = cached != m_references.end();
    double raysPerSecond = 0.0;
    if (reused) {
        std::rotate(m_references.begin(), cached, cached + 1);
        if (progress)
            progress(1.0);
    } else {
        ReferenceOptions options = m_options;
        options.lightRadius = settings.reference.lightRadius;
        std::optional<RayTracer> still;     // a still scene's, made for this trace alone
        const RayTracer& tracer = scene.moves() ? tracerFor(scene, buffer.cameraPosition) : still.emplace(scene, buffer.cameraPosition);
        m_references.insert(m_references.begin(), {key, traceReference(tracer, buffer, light, options, progress)});
        if (m_references.size() > m_keep)
            m_references.pop_back();
        ++m_referenceComputations;
        raysPerSecond = m_references.front().second.raysPerSecond();
    }

    AccuracyResult result = compareWithReference(buffer, m_references.front().second);
    result.referenceReused = reused;
    result.raysPerSecond = raysPerSecond;
    return result;
}

} // namespace shadowlab
