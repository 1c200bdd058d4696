#pragma once

#include "DepthOnlyDraw.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <optional>
#include <utility>

namespace shadowlab {

// Shadow pass: renders the casters' depth from the light into the shadow map. Casters
// entirely outside the light's volume are not drawn. Options from BiasSettings: front-face
// culling (only back faces reach the map) and glPolygonOffset. With a reversed-depth light
// frame it renders through glClipControl(zero-to-one), clearing to 0 and keeping the greater depth.
// Cut-out casters (DrawItem::alphaCutoff) draw with a variant that discards their holes, built on
// the first one drawn, unless `cutouts` is false (shadow.cutouts: cast them whole).
class DepthPass {
public:
    // Needs `gl`'s context current: looks up glClipControl (GL 4.5 or ARB_clip_control).
    explicit DepthPass(GlFunctions* gl);

    // Whether render() accepts frames with LightFrame::reversedDepth.
    bool supportsReversedDepth() const { return m_reversedDepth; }

    // Clears the map to the far depth: every lookup compares lit. Only what draws since the
    // last clear wrote (ShadowMap::written) is cleared again.
    void clear(ShadowMap& map, bool reversedDepth);
    // Clears, then draws the casters; with `slices` > 1 (map.slices) a whole 24-bit map is
    // cleared once in that many draws and drawn into its next depth slice between
    // (DepthSlices::beginDraw). Returns the number of draw calls issued.
    int render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, bool cutouts = true, int slices = 1);
    // The same for one tile of a map of several views (`tile` in texels), where the casters
    // cover `drawn` of it (core/CasterTexels.h; nullopt: anywhere): clears what earlier draws
    // wrote there and `drawn`, and draws within `drawn` only.
    // `casters`: only the still or the moving ones (a cache's draws, renderer/ShadowCache.h).
    int renderTile(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile,
                   const std::optional<QRect>& drawn, bool cutouts = true, int slices = 1, CasterSet casters = CasterSet::All);
    // Draws `casters` over what the tile holds, clearing nothing, in the map's current slice:
    // the moving casters over a cached copy of the still ones.
    int drawOver(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile,
                 const std::optional<QRect>& drawn, bool cutouts, CasterSet casters);
    void clearTile(ShadowMap& map, bool reversedDepth, const QRect& tile);

    // Texels cleared since the last call.
    qint64 takeClearedTexels() { return std::exchange(m_clearedTexels, 0); }

    // Whether the cut-out variant has been compiled (a scene with cut-outs was drawn).
    bool hasCutoutVariant() const { return m_draw.hasCutoutVariant(); }

private:
    int drawCasters(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile, const QRect& area,
                    const DepthSlice& slice, bool cutouts, CasterSet casters);
    void clearTileOnly(const ShadowMap& map, bool reversedDepth, const QRect& tile);

    GlFunctions* m_gl;
    DepthOnlyDraw m_draw;
    bool m_reversedDepth = false;
    qint64 m_clearedTexels = 0;
};

} // namespace shadowlab
