#include "MomentsBlurPass.h"

#include "PassState.h"
#include "ShaderConstants.h"

#include <cmath>

namespace shadowlab {

MomentsBlurPass::Program::Program(GlFunctions* gl, int radius)
    : program(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("momentsblur.frag"), {QStringLiteral("BLUR_RADIUS %1").arg(radius)}),
      source(program.uniform("uSource")),
      step(program.uniform("uStep")),
      weights(program.uniform("uWeights")),
      tileMin(program.uniform("uTileMin")),
      tileMax(program.uniform("uTileMax"))
{
}

MomentsBlurPass::MomentsBlurPass(GlFunctions* gl)
    : m_gl(gl),
      m_emptyVertexArray(makeVertexArray(gl)),
      m_sampler(makeSampler(gl))
{
    const GLuint s = m_sampler.id();
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    labelGlObject(GlLabelKind::Sampler, s, QStringLiteral("moments blur: nearest"));
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    labelGlObject(GlLabelKind::VertexArray, m_emptyVertexArray.id(), QStringLiteral("moments blur: no attributes"));
    m_gl->glBindVertexArray(0);
}

std::vector<float> MomentsBlurPass::weights(int width)
{
    const int radius = std::max(0, (width - 1) / 2);
    std::vector<float> w(std::size_t(radius) + 1, 1.0f);
    if (radius == 0)
        return w;
    const double sigma = double(width) / 4.0;
    double sum = 0.0;
    for (int i = 0; i <= radius; ++i) {
        const double g = std::exp(-0.5 * double(i * i) / (sigma * sigma));
        w[std::size_t(i)] = float(g);
        sum += i == 0 ? g : 2.0 * g;
    }
    for (float& v : w)
        v = float(double(v) / sum);
    return w;
}

int MomentsBlurPass::render(const MomentsMap& map, int width, const QRect& tile, const std::optional<QRect>& drawn)
{
    int draws = 0;
    const std::vector<float> w = weights(width);
    const QRect whole = tile.isEmpty() ? QRect(0, 0, map.width(), map.height()) : tile;
    const int radius = int(w.size()) - 1;
    // Where the blur changes anything: within its radius of what was drawn. The first axis also
    // covers the rows the second reads.
    const auto grown = [&](const QRect& r, int dx, int dy) { return r.isEmpty() ? r : r.adjusted(-dx, -dy, dx, dy) & whole; };
    const QRect second = grown(drawn.value_or(whole) & whole, radius, radius);
    const QRect first = grown(second, 0, radius);
    m_lastTexels = radius > 0 ? qint64(first.width()) * first.height() + qint64(second.width()) * second.height() : 0;
    m_lastWritten = radius > 0 ? second : QRect();
    if (radius > 0 && !second.isEmpty()) {
        float padded[kMaxBlurWeights] = {};
        std::copy_n(w.begin(), std::min<std::size_t>(w.size(), kMaxBlurWeights), padded);
        PassState state;
        state.viewport = whole;
        applyPassState(m_gl, state);
        std::unique_ptr<Program>& p = m_programs[radius];
        if (!p)
            p = std::make_unique<Program>(m_gl, radius);
        p->program.bind();
        p->program.set(p->source, 0);
        m_gl->glUniform1fv(p->weights, kMaxBlurWeights, padded);
        m_gl->glUniform2i(p->tileMin, whole.left(), whole.top());
        m_gl->glUniform2i(p->tileMax, whole.right(), whole.bottom());
        m_gl->glActiveTexture(GL_TEXTURE0);
        m_gl->glBindSampler(0, m_sampler.id());
        m_gl->glBindVertexArray(m_emptyVertexArray.id());
        // Horizontal into the scratch texture, vertical back into level 0 of the map; scissored
        // only to less than the whole map, as a scissor slows llvmpipe even where it cuts nothing.
        const QRect map0(0, 0, map.width(), map.height());
        const struct {
            GLuint framebuffer;
            GLuint source;
            GLint step[2];
            QRect area;
        } axes[2] = {{map.scratchFramebuffer(), map.texture(), {1, 0}, first}, {map.framebuffer(), map.scratchTexture(), {0, 1}, second}};
        for (const auto& axis : axes) {
            m_gl->glBindFramebuffer(GL_FRAMEBUFFER, axis.framebuffer);
            if (axis.area != map0) {
                m_gl->glEnable(GL_SCISSOR_TEST);
                m_gl->glScissor(axis.area.x(), axis.area.y(), axis.area.width(), axis.area.height());
            } else {
                m_gl->glDisable(GL_SCISSOR_TEST);
            }
            m_gl->glBindTexture(GL_TEXTURE_2D, axis.source);
            m_gl->glUniform2iv(p->step, 1, axis.step);
            m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
            ++draws;
        }
        m_gl->glDisable(GL_SCISSOR_TEST);
        m_gl->glBindVertexArray(0);
        m_gl->glBindSampler(0, 0);
        m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    }
    if (map.mipmaps()) {
        m_gl->glBindTexture(GL_TEXTURE_2D, map.texture());
        m_gl->glGenerateMipmap(GL_TEXTURE_2D);
        m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    }
    return draws;
}

} // namespace shadowlab
