#include "DepthPass.h"

#include "PassState.h"

namespace shadowlab {

DepthPass::Variant::Variant(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), defines),
      mvp(program.uniform("uLightModelViewProjection")),
      alphaCutoff(program.uniform("uAlphaCutoff"))
{
}

DepthPass::DepthPass(GlFunctions* gl) : m_gl(gl), m_plain(gl, {}), m_reversedDepth(hasClipControl()) {}

DepthPass::Variant& DepthPass::variant(bool cutout)
{
    if (!cutout)
        return m_plain;
    if (!m_cutout)
        m_cutout = std::make_unique<Variant>(m_gl, QStringList{QStringLiteral("ALPHA_CUTOUT"), QStringLiteral("CUTOUT_FULL_RESOLUTION")});
    return *m_cutout;
}

void DepthPass::clear(const ShadowMap& map, bool reversedDepth)
{
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState state;
    state.viewport = QRect(0, 0, map.width(), map.height());
    applyPassState(m_gl, state);
    m_gl->glClearDepth(reversedDepth ? 0.0 : 1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    m_gl->glClearDepth(1.0);
}

void DepthPass::clearTile(const ShadowMap& map, bool reversedDepth, const QRect& tile)
{
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState state;
    state.viewport = tile;
    applyPassState(m_gl, state);
    m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glScissor(tile.x(), tile.y(), tile.width(), tile.height());
    m_gl->glClearDepth(reversedDepth ? 0.0 : 1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    m_gl->glClearDepth(1.0);
    m_gl->glDisable(GL_SCISSOR_TEST);
}

int DepthPass::render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, const ShadowMap& map, bool cutouts)
{
    return renderTile(scene, light, bias, map, QRect(0, 0, map.width(), map.height()), cutouts);
}

int DepthPass::renderTile(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, const ShadowMap& map, const QRect& tile,
                          bool cutouts)
{
    const bool reversed = light.reversedDepth;   // the Renderer asks only when supportsReversedDepth()
    clearTile(map, reversed, tile);
    PassState state;
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
    state.polygonOffsetUnits = sign * float(bias.polygonUnits);
    applyPassState(m_gl, state);
    // Nothing outside the tile, whatever the rasteriser's guard band does.
    m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glScissor(tile.x(), tile.y(), tile.width(), tile.height());

    m_gl->glActiveTexture(GL_TEXTURE0);
    Variant* bound = nullptr;
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadow || isOutsideFrustum(light.viewProjection, item.bounds, clampDepth))
            continue;
        const bool cutout = cutouts && item.alphaCutoff > 0.0f;
        Variant& v = variant(cutout);
        if (&v != bound) {
            v.program.bind();
            bound = &v;
        }
        v.program.set(v.mvp, glm::mat4(light.depthViewProjection * item.model));
        if (cutout) {
            v.program.set(v.alphaCutoff, item.alphaCutoff);
            m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        }
        scene.draw(item, false);
        ++draws;
    }

    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindVertexArray(0);
    m_gl->glDisable(GL_SCISSOR_TEST);
    // GL's defaults again (no clamp, no offset, -1..1 depth) for whatever draws next here.
    applyPassState(m_gl, PassState{});
    return draws;
}

} // namespace shadowlab
