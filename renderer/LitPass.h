#pragma once

#include "DepthRangePass.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "MomentsMap.h"
#include "RenderTarget.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"
#include "ShadowViewFrames.h"

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace shadowlab {

// Lit pass: shades every object with Blinn-Phong or Phong and the selected shadow filter.
// Only the shader variant in use is compiled (on first use, then kept for switching back).
class LitPass {
public:
    explicit LitPass(GlFunctions* gl);

    // Draws into `target`, which must have a depth buffer. `map` may be null when shadows are off.
    // With `measure` the target must also have four RGBA32F attachments, which receive the
    // camera-relative position and shadow visibility, the geometric normal and a mask
    // (1 facing the light, 2 facing away, 0 background), and the ambient and direct light that
    // the colour is made of (ambient + visibility * direct; the background's ambient is the
    // clear colour). Returns the number of draw calls.
    // `depthRange` is the min/max depth mip of `map` for penumbra-only filtering; it must be
    // current (built from the map as it is) whenever usesDepthRange(settings). `moments` is the
    // moments map a moment technique reads (its sampler ShadowSampler::Moments); `map` still
    // gives the map's size then.
    int render(const GpuScene& scene, const CameraFrame& camera, const LightFrame& light, const Settings& settings,
               const ShadowMap* map, const RenderTarget& target, bool measure = false, const DepthRangePass* depthRange = nullptr,
               const MomentsMap* moments = nullptr);

    // Whether `settings` make the lit pass read the min/max depth mip (filter.early_out with a
    // technique that can skip its taps).
    static bool usesDepthRange(const Settings& settings);

    // The #defines that select the variant for `settings` (exposed for tests and diagnostics).
    static QStringList variantDefines(const Settings& settings, bool measure = false, bool reversedDepth = false);
    int compiledVariantCount() const { return int(m_programs.size()); }

    // The views the next render() reads when the settings use several (usesShadowViews()):
    // cascades or cube faces in the tiles of `map`. Null: none. Not owned; must outlive render().
    void setShadowViews(const ShadowViewFrames* views) { m_views = views; }

private:
    struct Program {
        explicit Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint model, normalMatrix, modelViewProjection, shadowModel, shadowWorld, normalOffset;
        GLint diffuse, baseColour, receives, shadowMap, shadowDepth, shadowMoments, shadowTexel, shadowUvWorld, shadowDepthRange, depthRange, depthRangeLevels;
        GLint lightPosition, lightDirection, biasSlope, biasMin;
        std::map<QByteArray, GLint> techniqueUniforms;  // the technique's own, looked up on first use
        GLint techniqueUniform(const QByteArray& name);
    };

    Program& programFor(const Settings& settings, bool measure, bool reversedDepth);
    void setViewUniforms(Program& p, const CameraFrame& camera, const Settings& settings, const ShadowMap& map);

    GlFunctions* m_gl;
    std::map<QString, std::unique_ptr<Program>> m_programs;
    std::vector<std::pair<double, std::size_t>> m_drawOrder;   // (distance, object), reused per frame
    const ShadowViewFrames* m_views = nullptr;
};

} // namespace shadowlab
