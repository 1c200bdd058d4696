#include "MomentsPass.h"

#include "MomentMath.h"
#include "PassState.h"
#include "ShadowTechnique.h"

namespace shadowlab {

MomentsPass::Program::Program(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("moments.vert"), QStringLiteral("moments.frag"), defines),
      mvp(program.uniform("uLightModelViewProjection")),
      depthRange(program.uniform("uDepthRange")),
      farPlane(program.uniform("uFarPlane")),
      exponentPositive(program.uniform("uExponentPositive")),
      exponentNegative(program.uniform("uExponentNegative")),
      alphaCutoff(program.uniform("uAlphaCutoff"))
{
}

MomentsPass::MomentsPass(GlFunctions* gl) : m_gl(gl), m_emptyVertexArray(makeVertexArray(gl))
{
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    labelGlObject(GlLabelKind::VertexArray, m_emptyVertexArray.id(), QStringLiteral("moments pass: far plane"));
    m_gl->glBindVertexArray(0);
}

QStringList MomentsPass::variantDefines(const Settings& settings, bool perspective)
{
    const ShadowTechnique& technique = shadowTechnique(settings.filter.mode);
    QStringList defines{QStringLiteral("SHADOW_TECHNIQUE \"%1\"").arg(technique.shaderFile), QStringLiteral("MOMENTS_PASS")};
    defines << technique.defines(settings);
    if (perspective)
        defines << QStringLiteral("LIGHT_PERSPECTIVE");
    return defines;
}

MomentsPass::Program& MomentsPass::program(const LightFrame& light, const Settings& settings, bool cutout)
{
    QStringList defines = variantDefines(settings, light.perspective);
    if (cutout)
        defines << QStringLiteral("ALPHA_CUTOUT") << QStringLiteral("CUTOUT_FULL_RESOLUTION");
    std::unique_ptr<Program>& p = m_programs[defines.join(QLatin1Char(';'))];
    if (!p)
        p = std::make_unique<Program>(m_gl, defines);
    return *p;
}

void MomentsPass::setLightUniforms(Program& p, const LightFrame& light, const Settings& settings)
{
    const MomentWarp warp = momentWarp(settings);
    p.program.set(p.depthRange, glm::vec2(float(light.volume.nearPlane), float(light.volume.farPlane)));
    p.program.set(p.exponentPositive, float(warp.positive));
    p.program.set(p.exponentNegative, float(warp.negative));
    p.program.set(p.farPlane, 0);
}

MomentsPass::Program& MomentsPass::begin(const LightFrame& light, const Settings& settings, const MomentsMap& map, const QRect& tile)
{
    Program* p = &program(light, settings, false);

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState fill;
    fill.viewport = tile.isEmpty() ? QRect(0, 0, map.width(), map.height()) : tile;
    applyPassState(m_gl, fill);
    // Only this tile's depth: the other views' tiles keep theirs.
    m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glScissor(fill.viewport.x(), fill.viewport.y(), fill.viewport.width(), fill.viewport.height());
    m_gl->glClearDepth(1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    m_gl->glDisable(GL_SCISSOR_TEST);

    p->program.bind();
    setLightUniforms(*p, light, settings);
    // The far plane's moments everywhere first (computed by the same encoding, so no copy of it
    // lives on the CPU).
    p->program.set(p->farPlane, 1);
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
    p->program.set(p->farPlane, 0);

    PassState state = fill;
    state.depthTest = true;
    state.depthClamp = true;    // casters before the fitted near plane still cast, as in the depth pass
    applyPassState(m_gl, state);
    return *p;
}

void MomentsPass::clear(const LightFrame& light, const Settings& settings, const MomentsMap& map, const QRect& tile)
{
    begin(light, settings, map, tile);
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
}

int MomentsPass::render(const GpuScene& scene, const LightFrame& light, const Settings& settings, const MomentsMap& map, const QRect& tile)
{
    // Every face: the moments must hold the nearest surface, receivers included, so a lit
    // receiver's filtered footprint is its own depth (front-face culling, the depth map's cure
    // for acne, would leave the far plane behind receivers, and the exponential warps read
    // that gap as light).
    Program& plain = begin(light, settings, map, tile);
    Program* cutoutProgram = nullptr;    // set up on the first cut-out caster
    Program* bound = &plain;
    m_gl->glActiveTexture(GL_TEXTURE0);
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadow || isOutsideFrustum(light.viewProjection, item.bounds, true))
            continue;
        const bool cutout = settings.shadow.cutouts && item.alphaCutoff > 0.0f;
        if (cutout && !cutoutProgram) {
            cutoutProgram = &program(light, settings, true);
            cutoutProgram->program.bind();
            setLightUniforms(*cutoutProgram, light, settings);
            bound = cutoutProgram;
        }
        Program& p = cutout ? *cutoutProgram : plain;
        if (&p != bound) {
            p.program.bind();
            bound = &p;
        }
        p.program.set(p.mvp, glm::mat4(light.depthViewProjection * item.model));
        if (cutout) {
            p.program.set(p.alphaCutoff, item.alphaCutoff);
            m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        }
        scene.draw(item, false);
        ++draws;
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
    return draws;
}

} // namespace shadowlab
