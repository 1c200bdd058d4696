#include "AccuracyMeter.h"

#include <algorithm>

namespace shadowlab {

AccuracyMeter::AccuracyMeter(ReferenceOptions options) : m_options(options) {}

AccuracyResult AccuracyMeter::measure(Renderer& renderer, const Settings& settings, QSize size,
                                      const std::function<void(double)>& progress)
{
    const VisibilityBuffer buffer = renderer.renderVisibility(settings, size);
    std::vector<bool> counts(std::size_t(buffer.pixelCount()));
    std::vector<float> measured(counts.size());
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        counts[std::size_t(i)] = buffer.mask(i) == VisibilityBuffer::FacingLight;
        measured[std::size_t(i)] = buffer.visibility(i);
    }

    AccuracyResult result;
    const ReferenceKey key = referenceKeyFor(settings, size, m_options.area ? m_options.samplesPerAxis : 0);
    auto cached = std::find_if(m_references.begin(), m_references.end(), [&](const auto& entry) { return entry.first == key; });
    result.referenceReused = cached != m_references.end();
    if (result.referenceReused) {
        std::rotate(m_references.begin(), cached, cached + 1);
        if (progress)
            progress(1.0);
    } else {
        ReferenceOptions options = m_options;
        options.lightRadius = settings.reference.lightRadius;
        const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
        m_references.insert(m_references.begin(), {key, traceReference(tracer, buffer, renderer.lightFrame(), options, progress)});
        if (m_references.size() > kCachedReferences)
            m_references.pop_back();
        ++m_referenceComputations;
        result.raysPerSecond = m_references.front().second.raysPerSecond();
    }

    const ReferenceVisibility& reference = m_references.front().second;
    result.hard = compareVisibility(measured, reference.hard, counts);
    if (!reference.area.empty())
        result.area = compareVisibility(measured, reference.area, counts);
    result.areaNoiseFloor = reference.areaNoiseFloor;
    result.frame = buffer.image;
    result.hardErrors = errorImage(buffer.image, measured, reference.hard, counts);
    return result;
}

} // namespace shadowlab
