#include "DepthPass.h"

#include "PassState.h"

namespace shadowlab {

DepthPass::DepthPass(GlFunctions* gl) : m_gl(gl), m_draw(gl, true), m_reversedDepth(hasClipControl()) {}

void DepthPass::clear(ShadowMap& map, bool reversedDepth)
{
    // Each tile where draws since its clear wrote: the rest reads cleared already. A map of one
    // view is cleared whole (the fast clear).
    const QRect whole(0, 0, map.width(), map.height());
    if (map.rows() * map.columns() == 1) {
        if (!map.written().written(whole).isEmpty())
            clearTileOnly(map, reversedDepth, whole);
        map.cleared(whole);
        return;
    }
    for (int row = 0; row < map.rows(); ++row) {
        for (int column = 0; column < map.columns(); ++column) {
            const QRect written = map.written().written(QRect(column * map.size(), row * map.size(), map.size(), map.size()));
            if (!written.isEmpty())
                clearTileOnly(map, reversedDepth, written);
        }
    }
    map.cleared(whole);
}

void DepthPass::clearTile(ShadowMap& map, bool reversedDepth, const QRect& tile)
{
    const QRect written = map.written().written(tile);
    if (written.isEmpty())
        return;
    clearTileOnly(map, reversedDepth, written);
    map.cleared(written);
}

void DepthPass::clearTileOnly(const ShadowMap& map, bool reversedDepth, const QRect& tile)
{
    m_clearedTexels += qint64(tile.width()) * tile.height();
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState state;
    state.viewport = tile;
    applyPassState(m_gl, state);
    // A clear of the whole map goes without a scissor: rasterisers clear a whole surface
    // fastest (docs/performance.md).
    const bool whole = tile == QRect(0, 0, map.width(), map.height());
    if (!whole) {
        m_gl->glEnable(GL_SCISSOR_TEST);
        m_gl->glScissor(tile.x(), tile.y(), tile.width(), tile.height());
    }
    m_gl->glClearDepth(reversedDepth ? 0.0 : 1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    m_gl->glClearDepth(1.0);
    m_gl->glDisable(GL_SCISSOR_TEST);
}

int DepthPass::render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, bool cutouts, int slices)
{
    return renderTile(scene, light, bias, map, QRect(0, 0, map.width(), map.height()), std::nullopt, cutouts, slices);
}

int DepthPass::renderTile(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile,
                          const std::optional<QRect>& drawn, bool cutouts, int slices, CasterSet casters)
{
    const bool reversed = light.reversedDepth;   // the Renderer asks only when supportsReversedDepth()
    const DepthSlices::Draw slice = map.beginDraw(tile, slices);
    // A sliced draw keeps what earlier slices left; any other clears what was written and what
    // it draws, and draws only where its casters are.
    const bool oneView = tile == QRect(0, 0, map.width(), map.height());
    const bool sliced = slice.slice.scale < 1.0;
    const QRect area = sliced && oneView ? tile : drawn.value_or(tile) & tile;
    // A map of one view is cleared whole, which is the fast clear of any rasteriser; a tile of
    // several only where it was or will be written (in a sliced pass, by the slices since the
    // last clear).
    const QRect clear = oneView ? tile : map.written().toClear(tile, area);
    if (slice.clear && !clear.isEmpty()) {
        clearTileOnly(map, reversed, clear);
        map.written().cleared(clear);
    }
    return drawCasters(scene, light, bias, map, tile, area, slice.slice, cutouts, casters);
}

int DepthPass::drawOver(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile,
                        const std::optional<QRect>& drawn, bool cutouts, CasterSet casters)
{
    return drawCasters(scene, light, bias, map, tile, drawn.value_or(tile) & tile, map.depthSlices().current(), cutouts, casters);
}

int DepthPass::drawCasters(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, ShadowMap& map, const QRect& tile,
                           const QRect& area, const DepthSlice& slice, bool cutouts, CasterSet casters)
{
    const bool reversed = light.reversedDepth;
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState state;
    state.depthRangeNear = slice.offset;
    state.depthRangeFar = slice.offset + slice.scale;
    state.viewport = tile;
    state.depthTest = true;
    state.depthFunc = reversed ? GL_GREATER : GL_LESS;
    state.zeroToOneDepth = reversed;
    // The fitted near plane is the nearest receiver, not the nearest caster: casters between
    // the light and the near plane still cast, so clamp their depth to the near plane instead
    // of clipping them away (a perspective light's side planes still clip what is behind it).
    const bool clampDepth = true;
    state.depthClamp = clampDepth;
    state.cullFace = bias.cullFront ? GL_FRONT : GL_NONE;
    // Offsets push depth away from the light, which is downward with reversed depth.
    const float sign = reversed ? -1.0f : 1.0f;
    state.polygonOffsetFactor = sign * float(bias.polygonFactor);
    // Units are steps of the depth buffer, the same wherever they land; in a slice 1/n of the
    // range a step is n steps of conventional depth, so the units shrink by the slice's scale
    // to push by the same depth (the factor's slope term follows the range on its own).
    state.polygonOffsetUnits = sign * float(bias.polygonUnits * slice.scale);
    applyPassState(m_gl, state);
    // Nothing outside the area, whatever the rasteriser's guard band does.
    m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glScissor(area.x(), area.y(), area.width(), area.height());
    map.written().drew(area);

    const int draws = m_draw.draw(scene, {.viewProjection = light.depthViewProjection, .culling = light.viewProjection, .clampDepth = clampDepth,
                                          .castersOnly = true, .light = bias.skipFloors ? &light : nullptr, .cutouts = cutouts,
                                          .casters = casters});
    m_gl->glDisable(GL_SCISSOR_TEST);
    // GL's defaults again (no clamp, no offset, -1..1 depth) for whatever draws next here.
    applyPassState(m_gl, PassState{});
    return draws;
}

} // namespace shadowlab
