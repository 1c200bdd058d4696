#include "DepthRangePass.h"

#include "PassState.h"
#include "RenderError.h"

#include <algorithm>

namespace shadowlab {

namespace {

constexpr GLuint kSourceUnit = 0;

} // namespace

DepthRangePass::DepthRangePass(GlFunctions* gl, Contents contents)
    : m_gl(gl),
      m_contents(contents),
      m_fromDepth(std::make_unique<ShaderProgram>(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("depthrange.frag"),
                                                  contents == Contents::Written ? QStringList{QStringLiteral("FROM_DEPTH"), QStringLiteral("WRITTEN_ONLY")}
                                                                                : QStringList{QStringLiteral("FROM_DEPTH")})),
      m_fromRange(std::make_unique<ShaderProgram>(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("depthrange.frag"), QStringList{})),
      m_emptyVertexArray(makeVertexArray(gl)),
      m_framebuffer(makeFramebuffer(gl))
{
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    labelGlObject(GlLabelKind::VertexArray, m_emptyVertexArray.id(), QStringLiteral("depth range: no attributes"));
    m_gl->glBindVertexArray(0);
}

void DepthRangePass::allocate(int mapSize)
{
    m_texture = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_texture.id());
    // Level 0 halves the map rounding up, so it covers every map texel; the rest follow GL's
    // rule for a complete mip chain (halving, rounded down), whose odd leftovers the pass folds
    // into the last texel.
    int levels = 0;
    for (int size = (mapSize + 1) / 2; ; size /= 2) {
        m_gl->glTexImage2D(GL_TEXTURE_2D, levels++, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, nullptr);
        if (size == 1)
            break;
    }
    // Read with texelFetch only; nearest filtering keeps every level complete.
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, std::max(levels - 1, 0));
    labelGlObject(GlLabelKind::Texture, m_texture.id(), QStringLiteral("shadow map min/max depth mip"));
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_mapSize = mapSize;
    m_levels = levels;
}

void DepthRangePass::build(const ShadowMap& map, bool reversedDepth)
{
    if (!m_texture || map.size() != m_mapSize)
        allocate(map.size());
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    labelGlObject(GlLabelKind::Framebuffer, m_framebuffer.id(), QStringLiteral("depth range pass"));
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glActiveTexture(GL_TEXTURE0 + kSourceUnit);

    for (int level = 0, size = (map.size() + 1) / 2; level < m_levels; ++level, size = std::max(size / 2, 1)) {
        m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_texture.id(), level);
        if (level == 0) {
            const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE)
                throw RenderError(QStringLiteral("the min/max depth mip's framebuffer is incomplete (status 0x%1)").arg(status, 0, 16));
        }
        PassState state;
        state.viewport = QRect(0, 0, size, size);
        applyPassState(m_gl, state);
        ShaderProgram& program = level == 0 ? *m_fromDepth : *m_fromRange;
        program.bind();
        program.set(program.uniform("uSource"), int(kSourceUnit));
        if (level == 0 && m_contents == Contents::Written)
            program.set(program.uniform("uEmpty"), reversedDepth ? 0.0f : 1.0f);
        if (level == 0) {
            m_gl->glBindTexture(GL_TEXTURE_2D, map.texture());
            m_gl->glBindSampler(kSourceUnit, map.sampler(ShadowSampler::RawNearest));
        } else {
            // Only the level read is in the texture's range while the next one is drawn: no
            // feedback loop through the attached level.
            m_gl->glBindTexture(GL_TEXTURE_2D, m_texture.id());
            m_gl->glBindSampler(kSourceUnit, 0);
            m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 1);
            m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 1);
        }
        m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, m_texture.id());
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, m_levels - 1);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindSampler(kSourceUnit, 0);
    m_gl->glBindVertexArray(0);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
}

std::optional<std::pair<float, float>> DepthRangePass::readTotal()
{
    if (!m_texture || m_levels < 1)
        return std::nullopt;
    float range[2] = {0.0f, 0.0f};
    m_gl->glBindTexture(GL_TEXTURE_2D, m_texture.id());
    m_gl->glGetTexImage(GL_TEXTURE_2D, m_levels - 1, GL_RG, GL_FLOAT, range);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    if (!(range[0] <= range[1]))
        return std::nullopt;    // the neutral (1e30, -1e30): nothing written
    return std::pair{range[0], range[1]};
}

} // namespace shadowlab
