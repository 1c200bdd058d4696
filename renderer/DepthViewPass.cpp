#include "DepthViewPass.h"

#include "MomentMath.h"
#include "PassState.h"
#include "ShadowTechnique.h"

#include <algorithm>

namespace shadowlab {

DepthViewPass::Program::Program(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("depthview.frag"), defines),
      depth(program.uniform("uDepth")),
      nearPlane(program.uniform("uNear")),
      farPlane(program.uniform("uFar")),
      uvOffset(program.uniform("uUvOffset")),
      uvScale(program.uniform("uUvScale")),
      span(program.uniform("uSpan")),
      slice(program.uniform("uShadowSlice"))
{
}

DepthViewPass::MomentsProgram::MomentsProgram(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("momentsview.frag"), defines),
      moments(program.uniform("uMoments")),
      channel(program.uniform("uChannel")),
      exponentPositive(program.uniform("uExponentPositive")),
      exponentNegative(program.uniform("uExponentNegative")),
      uvOffset(program.uniform("uUvOffset")),
      uvScale(program.uniform("uUvScale"))
{
}

DepthViewPass::DepthViewPass(GlFunctions* gl)
    : m_gl(gl), m_emptyVertexArray(makeVertexArray(gl)), m_sampler(makeSampler(gl)), m_programs(gl), m_momentsPrograms(gl)
{
    // A sampler of our own: the texture's parameters belong to the renderer, and the compare
    // mode of its lit-pass sampler must not leak into this raw read.
    const GLuint s = m_sampler.id();
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    labelGlObject(GlLabelKind::Sampler, s, QStringLiteral("depth view: raw depth"));
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    labelGlObject(GlLabelKind::VertexArray, m_emptyVertexArray.id(), QStringLiteral("depth view: no attributes"));
    m_gl->glBindVertexArray(0);
}

DepthViewPass::~DepthViewPass() = default;

std::optional<DepthSpan> DepthViewPass::measure(const ShadowMap& map, const LightFrame& light)
{
    if (!map.texture())
        return std::nullopt;
    if (!m_range)
        m_range = std::make_unique<DepthRangePass>(m_gl, DepthRangePass::Contents::Written);
    m_range->build(map, light.reversedDepth);
    const auto raw = m_range->readTotal();
    if (!raw)
        return std::nullopt;
    if (light.reversedDepth)
        return DepthSpan{1.0 - raw->second, 1.0 - raw->first};
    return DepthSpan{raw->first, raw->second};
}

void DepthViewPass::render(const ShadowMap& map, const LightFrame& light, const RenderTarget& target, const QRectF& visible,
                           const QRect& viewport, const std::optional<DepthSpan>& span)
{
    QStringList defines;
    if (light.perspective)
        defines << QStringLiteral("LINEARIZE");
    if (light.reversedDepth)
        defines << QStringLiteral("REVERSED_Z");
    Program& p = m_programs.get(defines);

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    PassState state;
    state.viewport = viewport.isEmpty() ? QRect(QPoint(0, 0), target.size) : viewport;
    applyPassState(m_gl, state);

    p.program.bind();
    p.program.set(p.depth, 0);
    p.program.set(p.nearPlane, float(light.nearPlane));
    p.program.set(p.farPlane, float(light.farPlane));
    p.program.set(p.uvOffset, glm::vec2(float(visible.x()), float(visible.y())));
    p.program.set(p.uvScale, glm::vec2(float(visible.width()), float(visible.height())));
    const DepthSpan shown = span.value_or(DepthSpan{});
    p.program.set(p.span, glm::vec2(float(shown.nearest), float(shown.farthest)));
    p.program.set(p.slice, map.slice().uniform());
    draw(map.texture());
}

void DepthViewPass::renderMoments(GLuint momentsTexture, const Settings& settings, const RenderTarget& target, const QRectF& visible,
                                  const QRect& viewport)
{
    const ShadowTechnique& technique = shadowTechnique(settings.filter.mode);
    QStringList defines{QStringLiteral("SHADOW_TECHNIQUE \"%1\"").arg(technique.shaderFile), QStringLiteral("MOMENTS_VIEW")};
    defines << technique.defines(settings);
    MomentsProgram& p = m_momentsPrograms.get(defines);

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    PassState state;
    state.viewport = viewport.isEmpty() ? QRect(QPoint(0, 0), target.size) : viewport;
    applyPassState(m_gl, state);
    const MomentWarp warp = momentWarp(settings);
    p.program.bind();
    p.program.set(p.moments, 0);
    p.program.set(p.channel, settings.moments.view - 1);
    p.program.set(p.exponentPositive, float(warp.positive));
    p.program.set(p.exponentNegative, float(warp.negative));
    p.program.set(p.uvOffset, glm::vec2(float(visible.x()), float(visible.y())));
    p.program.set(p.uvScale, glm::vec2(float(visible.width()), float(visible.height())));
    draw(momentsTexture);
}

void DepthViewPass::draw(GLuint texture)
{
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_gl->glBindTexture(GL_TEXTURE_2D, texture);
    m_gl->glBindSampler(0, m_sampler.id());
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
    m_gl->glBindVertexArray(0);
    m_gl->glBindSampler(0, 0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
}

void DepthViewPass::renderLegend(const RenderTarget& target, const QRect& viewport)
{
    if (viewport.isEmpty())
        return;
    Program& p = m_programs.get({QStringLiteral("LEGEND")});
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    PassState state;
    state.viewport = viewport;
    applyPassState(m_gl, state);
    p.program.bind();
    p.program.set(p.uvOffset, glm::vec2(0.0f));
    p.program.set(p.uvScale, glm::vec2(1.0f));
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
    m_gl->glBindVertexArray(0);
}

void DepthViewPass::renderOverlay(const RenderTarget& target, const QImage& image)
{
    if (image.isNull() || target.size.isEmpty())
        return;
    const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
    const bool fresh = !m_overlay;
    if (fresh)
        m_overlay = makeTexture(m_gl);
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_overlay.id());
    if (fresh)  // a texture name is an object only once bound
        labelGlObject(GlLabelKind::Texture, m_overlay.id(), QStringLiteral("depth view: legend and outlines"));
    m_gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.width(), rgba.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.constBits());
    Program& p = m_programs.get({QStringLiteral("OVERLAY")});
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    PassState state;
    state.viewport = QRect(QPoint(0, 0), target.size);
    state.blend = true;     // premultiplied alpha
    state.blendDestinationRgb = GL_ONE_MINUS_SRC_ALPHA;
    state.blendDestinationAlpha = GL_ONE_MINUS_SRC_ALPHA;
    applyPassState(m_gl, state);
    p.program.bind();
    p.program.set(p.depth, 0);
    p.program.set(p.uvOffset, glm::vec2(0.0f));
    p.program.set(p.uvScale, glm::vec2(1.0f));
    m_gl->glBindSampler(0, m_sampler.id());
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
    m_gl->glBindVertexArray(0);
    m_gl->glBindSampler(0, 0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    applyPassState(m_gl, PassState{});
}

} // namespace shadowlab
