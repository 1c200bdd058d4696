#include "MomentsPass.h"

#include "MomentMath.h"
#include "PassState.h"
#include "SceneLayout.h"
#include "SettingsKeys.h"
#include "ShadowReach.h"
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

MomentsPass::MomentsPass(GlFunctions* gl) : m_gl(gl), m_emptyVertexArray(makeVertexArray(gl)), m_programs(gl)
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

bool MomentsPass::leavesOutFloors(const Settings& settings)
{
    return shadowTechnique(settings.filter.mode).coverage && settings.bias.skipFloors;
}

bool MomentsPass::drawsFloorsAroundCasters(const Settings& settings)
{
    return !shadowTechnique(settings.filter.mode).coverage && settings.bias.skipFloors && tapReachTexels(settings).has_value();
}

MomentsPass::Program& MomentsPass::program(const LightFrame& light, const Settings& settings, bool cutout)
{
    QStringList defines = variantDefines(settings, light.perspective);
    if (cutout)
        defines << QStringLiteral("ALPHA_CUTOUT") << QStringLiteral("CUTOUT_FULL_RESOLUTION");
    return m_programs.get(defines);
}

void MomentsPass::setLightUniforms(Program& p, const LightFrame& light, const Settings& settings)
{
    const MomentWarp warp = momentWarp(settings);
    p.program.set(p.depthRange, glm::vec2(float(light.volume.nearPlane), float(light.volume.farPlane)));
    p.program.set(p.exponentPositive, float(warp.positive));
    p.program.set(p.exponentNegative, float(warp.negative));
    p.program.set(p.farPlane, 0);
}

QString MomentsPass::encoding(const LightFrame& light, const Settings& settings)
{
    const MomentWarp warp = momentWarp(settings);
    return variantDefines(settings, light.perspective).join(QLatin1Char(';'))
        + QStringLiteral(";%1;%2;%3").arg(toString(settings.moments.format)).arg(warp.positive, 0, 'g', 17).arg(warp.negative, 0, 'g', 17);
}

MomentsPass::Program& MomentsPass::begin(const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& clear)
{
    Program* p = &program(light, settings, false);
    m_clearedTexels += qint64(clear.width()) * clear.height();

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    PassState fill;
    fill.viewport = clear;
    applyPassState(m_gl, fill);
    p->program.bind();
    setLightUniforms(*p, light, settings);
    if (clear.isEmpty())
        return *p;      // drawn over what is there
    // The far plane's moments, computed by the technique's own encoding: drawn the first time,
    // then cleared to the value that drawing gave (a rasteriser clears a whole surface fastest:
    // docs/performance.md). Coverage makes them zeros.
    const QString key = encoding(light, settings);
    const bool whole = clear == QRect(0, 0, map.width(), map.height());
    const bool zeros = shadowTechnique(settings.filter.mode).coverage;
    const auto known = m_farMoments.find(key);
    m_gl->glClearDepth(1.0);
    if (zeros || known != m_farMoments.end()) {
        const std::array<GLfloat, 4> value = zeros ? std::array<GLfloat, 4>{} : known->second;
        if (!whole) {
            m_gl->glEnable(GL_SCISSOR_TEST);
            m_gl->glScissor(clear.x(), clear.y(), clear.width(), clear.height());
        }
        m_gl->glClearBufferfv(GL_COLOR, 0, value.data());
        m_gl->glClear(GL_DEPTH_BUFFER_BIT);
        m_gl->glDisable(GL_SCISSOR_TEST);
    } else {
        // Only what is cleared: the rest of the tile, and the other views' tiles, keep theirs.
        m_gl->glEnable(GL_SCISSOR_TEST);
        m_gl->glScissor(clear.x(), clear.y(), clear.width(), clear.height());
        m_gl->glClear(GL_DEPTH_BUFFER_BIT);
        p->program.set(p->farPlane, 1);
        m_gl->glBindVertexArray(m_emptyVertexArray.id());
        m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
        p->program.set(p->farPlane, 0);
        m_gl->glDisable(GL_SCISSOR_TEST);
        std::array<GLfloat, 4> value{};
        m_gl->glReadPixels(clear.x(), clear.y(), 1, 1, GL_RGBA, GL_FLOAT, value.data());
        m_farMoments.emplace(key, value);
    }
    map.written().cleared(clear);
    return *p;
}

MomentsPass::Program& MomentsPass::clearFirst(const LightFrame& light, const Settings& settings, MomentsMap& map, const std::vector<QRect>& rects)
{
    Program* p = &begin(light, settings, map, rects.empty() ? QRect() : rects.front());
    for (std::size_t i = 1; i < rects.size(); ++i)
        p = &begin(light, settings, map, rects[i]);
    return *p;
}

void MomentsPass::clear(const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& tile)
{
    map.encodedBy(encoding(light, settings));
    const QRect whole = tile.isEmpty() ? QRect(0, 0, map.width(), map.height()) : tile;
    // Each tile's written texels; the rest holds the far plane's moments already.
    for (int row = 0; row < map.rows(); ++row) {
        for (int column = 0; column < map.columns(); ++column) {
            const QRect tileRect = QRect(column * map.size(), row * map.size(), map.size(), map.size()) & whole;
            const QRect written = map.written().written(tileRect);
            if (!written.isEmpty())
                begin(light, settings, map, map.rows() * map.columns() == 1 ? tileRect : written);
        }
    }
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
}

int MomentsPass::drawInPieces(const GpuScene& scene, const DrawItem& item, const std::vector<QRect>& pieces, const QRect& area, bool scissored)
{
    // A floor only around the casters, once in each piece; then the pass's scissor again.
    int draws = 0;
    m_gl->glEnable(GL_SCISSOR_TEST);
    for (const QRect& piece : pieces) {
        const QRect cut = piece & area;
        if (cut.isEmpty())
            continue;
        m_gl->glScissor(cut.x(), cut.y(), cut.width(), cut.height());
        scene.draw(item, false);
        ++draws;
    }
    m_gl->glScissor(area.x(), area.y(), area.width(), area.height());
    if (!scissored)
        m_gl->glDisable(GL_SCISSOR_TEST);
    return draws;
}

int MomentsPass::render(const GpuScene& scene, const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& tile,
                        const Area& within, CasterSet casters, bool clear)
{
    // Every face: without coverage the moments must hold the nearest surface, receivers
    // included, so a lit receiver's filtered footprint is its own depth (front-face culling,
    // the depth map's cure for acne, would leave the far plane behind receivers, and the
    // exponential warps read that gap as light). With coverage, floors are left out.
    const bool floorsOut = leavesOutFloors(settings);
    map.encodedBy(encoding(light, settings));
    const QRect whole = tile.isEmpty() ? QRect(0, 0, map.width(), map.height()) : tile;
    const QRect area = within.drawn.value_or(whole) & whole;
    // A map of one view is cleared whole (a GPU's fast clear), a tile of several, or a map drawn
    // in part under RasteriserTuning::clearsWrittenMoments, only where it was or will be written.
    const bool oneView = whole == QRect(0, 0, map.width(), map.height());
    const bool clearsWhole = oneView && !(m_clearsWritten && area != whole);
    const std::vector<QRect> pieces = within.pieces.empty() ? std::vector<QRect>{area} : within.pieces;
    Program& plain = clearFirst(light, settings, map, !clear ? std::vector<QRect>{} : clearsWhole ? std::vector<QRect>{whole}
                                                                                               : map.written().piecesToClear(whole, pieces, kMostPieces));
    if (clear && !clearsWhole)
        map.written().clearedPieces(whole);
    PassState state;
    state.viewport = whole;
    state.depthTest = true;
    state.depthClamp = true;    // casters before the fitted near plane still cast, as in the depth pass
    applyPassState(m_gl, state);
    const bool scissored = !oneView || area != whole;
    if (scissored) {
        m_gl->glEnable(GL_SCISSOR_TEST);
        m_gl->glScissor(area.x(), area.y(), area.width(), area.height());
    }
    // A caster draws only inside its own piece (its box's image with a texel of margin,
    // core/CasterTexels.h), so what the pieces clear and record is all it writes; the scissor is
    // their bounds.
    for (const QRect& piece : pieces)
        map.written().drew(piece & area);
    Program* cutoutProgram = nullptr;    // set up on the first cut-out caster
    Program* bound = &plain;
    m_gl->glActiveTexture(GL_TEXTURE0);
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadow || !drawsItem(casters, item) || (floorsOut && shadowsNothing(item, light))
            || isOutsideFrustum(light.viewProjection, item.bounds, true))
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
        if (within.floorsInPieces && shadowsNothing(item, light)) {
            draws += drawInPieces(scene, item, pieces, area, scissored);
            continue;
        }
        scene.draw(item, false);
        ++draws;
    }
    m_gl->glDisable(GL_SCISSOR_TEST);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
    return draws;
}

} // namespace shadowlab
