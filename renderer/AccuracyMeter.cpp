#include "AccuracyMeter.h"

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
    const ReferenceKey key{settings.scene,           settings.camera,         size, settings.light.position, settings.light.target,
                           settings.light.projection, settings.reference.lightRadius};
    result.referenceReused = m_key == key;
    if (!result.referenceReused) {
        ReferenceOptions options = m_options;
        options.lightRadius = settings.reference.lightRadius;
        const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
        m_reference = traceReference(tracer, buffer, renderer.lightFrame(), options, progress);
        m_key = key;
        ++m_referenceComputations;
        result.raysPerSecond = m_reference.raysPerSecond();
    } else if (progress) {
        progress(1.0);
    }

    result.hard = compareVisibility(measured, m_reference.hard, counts);
    if (!m_reference.area.empty())
        result.area = compareVisibility(measured, m_reference.area, counts);
    result.areaNoiseFloor = m_reference.areaNoiseFloor;
    result.frame = buffer.image;
    result.hardErrors = errorImage(buffer.image, measured, m_reference.hard, counts);
    return result;
}

} // namespace shadowlab
