#pragma once

#include "RayTracer.h"
#include "Scene.h"
#include "ShadowMetrics.h"
#include "ShadowReference.h"
#include "Ssim.h"
#include "VisibilityBuffer.h"

#include <QImage>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

struct AccuracyResult {
    ErrorMetrics hard;              // against one shadow ray per pixel
    ErrorMetrics area;              // against the disk light (pixels == 0 when not traced)
    // The frame as a person sees it, shaded with the measured shadow term, against the same
    // frame shaded with the hard reference's: their mean SSIM (Ssim.h) on luma, 1 when alike.
    double ssim = 1.0;
    // The same against the frame shaded with the area reference, where it was traced: a soft
    // technique's right picture is that one.
    std::optional<double> areaSsim;
    QImage frame;                   // the shaded frame that was measured
    QImage hardErrors;              // false shadow / false light over the greyed frame
    QImage hardHeat;                // |V - V_ref| over the greyed frame (errorHeatImage())
    double areaNoiseFloor = 0.0;
    double raysPerSecond = 0.0;     // of the reference computation, when it ran for this call
    bool referenceReused = false;
};

// The one comparison of a measured shadow term with its reference, used by the accuracy dock,
// `report` and the tests: metrics against the hard and (when traced) the area reference, the
// SSIM of the frame against it shaded with the hard reference, and the error image over the
// measured frame. Only light-facing pixels count; the SSIM covers the whole frame, where the
// rest is alike.
AccuracyResult compareWithReference(const VisibilityBuffer& buffer, const ReferenceVisibility& reference);

// `buffer`'s frame shaded again from its light terms with `visibility` (one entry a pixel):
// ambient + visibility * direct per channel, clamped to 1 as the display clamps it, as luma
// Y' = 0.299 R + 0.587 G + 0.114 B (the weights the SSIM paper's images were made grey with).
// Pixels without light terms are 0.
GreyImage shadedLuma(const VisibilityBuffer& buffer, const std::vector<float>& visibility);

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

private:
    // A few references, newest first: a sweep that alternates between light placements (ortho
    // and perspective, say) must not trace each again on every switch.
    static constexpr std::size_t kCachedReferences = 4;
public:
    // Keeps at least `count` references: a report over N instants of an animation measures each
    // configuration at all N, and each needs its instant's reference again.
    void keepReferences(std::size_t count) { m_keep = std::max(count, kCachedReferences); }

private:
    std::size_t m_keep = kCachedReferences;

    // The tracer of the last moving scene traced, kept for the next instant of the same scene:
    // its moving casters are moved (RayTracer::pose), not built again. A still scene's is not kept.
    const RayTracer& tracerFor(const Scene& scene, const glm::dvec3& origin);

    ReferenceOptions m_options;
    std::vector<std::pair<ReferenceKey, ReferenceVisibility>> m_references;
    struct TracedScene {
        QString name;
        QByteArray identity;
        glm::dvec3 origin{0.0};
        std::size_t meshes = 0;
        std::vector<bool> casts;
        bool operator==(const TracedScene&) const = default;
    };
    TracedScene m_traced;
    std::unique_ptr<RayTracer> m_tracer;
    int m_referenceComputations = 0;
};

} // namespace shadowlab
