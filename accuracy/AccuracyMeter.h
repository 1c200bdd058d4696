#pragma once

#include "Scene.h"
#include "ShadowMetrics.h"
#include "ShadowReference.h"
#include "VisibilityBuffer.h"

#include <QImage>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace shadowlab {

struct AccuracyResult {
    ErrorMetrics hard;              // against one shadow ray per pixel
    ErrorMetrics area;              // against the disk light (pixels == 0 when not traced)
    QImage frame;                   // the shaded frame that was measured
    QImage hardErrors;              // false shadow / false light over the greyed frame
    double areaNoiseFloor = 0.0;
    double raysPerSecond = 0.0;     // of the reference computation, when it ran for this call
    bool referenceReused = false;
};

// The one comparison of a measured shadow term with its reference, used by the accuracy dock,
// `report` and the tests: metrics against the hard and (when traced) the area reference, and
// the error image over the measured frame. Only light-facing pixels count.
AccuracyResult compareWithReference(const VisibilityBuffer& buffer, const ReferenceVisibility& reference);

// Measures a renderer's shadow term against the ray-traced reference for the same pixels.
// The reference depends only on scene, camera, image size and light placement (not on map
// size, bias or filter), so it is traced once and reused while those stay the same.
class AccuracyMeter {
public:
    explicit AccuracyMeter(ReferenceOptions options = {});

    // `buffer` is what the renderer read back for `settings` (Renderer::renderVisibility()),
    // `scene` and `light` what it drew with. Throws TraceError when Embree fails.
    AccuracyResult measure(const VisibilityBuffer& buffer, const Scene& scene, const LightFrame& light, const Settings& settings,
                           const std::function<void(double)>& progress = {});

    int referenceComputations() const { return m_referenceComputations; }
    const ReferenceOptions& options() const { return m_options; }

private:
    // A few references, newest first: a sweep that alternates between light placements (ortho
    // and perspective, say) must not trace each again on every switch.
    static constexpr std::size_t kCachedReferences = 4;

    ReferenceOptions m_options;
    std::vector<std::pair<ReferenceKey, ReferenceVisibility>> m_references;
    int m_referenceComputations = 0;
};

} // namespace shadowlab
