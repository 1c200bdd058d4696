#include "DepthRangePass.h"

#include "CasterTexels.h"
#include "PassState.h"
#include "RenderError.h"

#include <algorithm>

namespace shadowlab {

namespace {

constexpr GLuint kSourceUnit = 0;

} // namespace

DepthRangePass::Program::Program(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("fullscreen.vert"), QStringLiteral("depthrange.frag"), defines),
      source(program.uniform("uSource")),
      sourceSize(program.uniform("uSourceSize")),
      shadowSlice(program.uniform("uShadowSlice")),
      empty(program.uniform("uEmpty"))
{
}

DepthRangePass::DepthRangePass(GlFunctions* gl, Contents contents)
    : m_gl(gl),
      m_contents(contents),
      m_fromDepth(std::make_unique<Program>(gl, contents == Contents::Written ? QStringList{QStringLiteral("FROM_DEPTH"), QStringLiteral("WRITTEN_ONLY")}
                                                                               : QStringList{QStringLiteral("FROM_DEPTH")})),
      m_fromRange(std::make_unique<Program>(gl, QStringList{})),
      m_emptyVertexArray(makeVertexArray(gl)),
      m_framebuffer(makeFramebuffer(gl)),
      m_atlasFramebuffer(makeFramebuffer(gl))
{
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    labelGlObject(GlLabelKind::VertexArray, m_emptyVertexArray.id(), QStringLiteral("depth range: no attributes"));
    m_gl->glBindVertexArray(0);
}

void DepthRangePass::allocate(QSize mapSize)
{
    // Level 0 covers 4 x 4 map texels a texel, rounding up, so it covers every map texel; the rest follow GL's
    // rule for a complete mip chain (halving each axis, rounded down, to 1), whose odd leftovers
    // the pass folds into the last texel. Level 0 is drawn straight into the atlas; the chain
    // holds levels 1 and up (its level j is level j + 1), each drawn from the one before and
    // then copied over.
    const QSize levelZero((mapSize.width() + kLevelZeroBlock - 1) / kLevelZeroBlock, (mapSize.height() + kLevelZeroBlock - 1) / kLevelZeroBlock);
    m_origins = {QPoint(0, 0)};
    m_sizes = {levelZero};
    int columnWidth = 0, columnHeight = 0;
    while (m_sizes.back() != QSize(1, 1) && int(m_sizes.size()) < kMaxDepthRangeLevels) {
        const int level = int(m_sizes.size());
        const QSize size(std::max(levelZero.width() >> level, 1), std::max(levelZero.height() >> level, 1));
        m_origins.emplace_back(levelZero.width(), columnHeight);
        m_sizes.push_back(size);
        columnWidth = std::max(columnWidth, size.width());
        columnHeight += size.height();
    }
    const QSize atlas(levelZero.width() + columnWidth, std::max(levelZero.height(), columnHeight));

    m_atlas = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_atlas.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, atlas.width(), atlas.height(), 0, GL_RG, GL_FLOAT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    labelGlObject(GlLabelKind::Texture, m_atlas.id(), QStringLiteral("shadow map min/max depth atlas"));

    m_chain = makeTexture(m_gl);
    if (levels() > 1) {
        m_gl->glBindTexture(GL_TEXTURE_2D, m_chain.id());
        for (int level = 1; level < levels(); ++level) {
            const QSize size = levelSize(level);
            m_gl->glTexImage2D(GL_TEXTURE_2D, level - 1, GL_RG32F, size.width(), size.height(), 0, GL_RG, GL_FLOAT, nullptr);
        }
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels() - 2);
        // Read with texelFetch only; nearest filtering keeps every level complete.
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        labelGlObject(GlLabelKind::Texture, m_chain.id(), QStringLiteral("shadow map min/max depth mip chain"));
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_mapSize = mapSize;
}

namespace {

// The level-0 texels whose blocks of map texels hold any of `texels`.
std::vector<QRect> levelZeroOver(const std::vector<QRect>& texels, QSize levelZero)
{
    const int block = DepthRangePass::kLevelZeroBlock;
    std::vector<QRect> over;
    for (const QRect& r : texels) {
        if (!r.isEmpty())
            over.push_back(QRect(QPoint(r.left() / block, r.top() / block), QPoint(r.right() / block, r.bottom() / block))
                           & QRect(QPoint(0, 0), levelZero));
    }
    return over;
}

} // namespace

std::vector<QRect> DepthRangePass::levelZeroAreas(const ShadowMap& map, const std::vector<QRect>* written)
{
    // Level 0 over what is written now and what was at the last build, where both are known
    // and the map is the same texture; the whole level otherwise.
    std::optional<std::vector<QRect>> now;
    if (written != nullptr && m_contents == Contents::All)
        now = levelZeroOver(*written, levelSize(0));
    std::vector<QRect> levelZero{QRect(QPoint(0, 0), levelSize(0))};
    if (now && m_lastWritten && m_source == map.texture() && m_sourceReversed == map.reversedDepth()) {
        std::vector<QRect> both = *now;
        both.insert(both.end(), m_lastWritten->begin(), m_lastWritten->end());
        levelZero = joinOverlapping(both, kMostAreas);
    }
    m_lastWritten = std::move(now);
    m_source = map.texture();
    m_sourceReversed = map.reversedDepth();
    return levelZero;
}

void DepthRangePass::build(const ShadowMap& map, bool reversedDepth, const std::vector<QRect>* written)
{
    const QSize mapSize(map.width(), map.height());
    if (!m_atlas || mapSize != m_mapSize) {
        allocate(mapSize);
        m_lastWritten.reset();
    }
    const std::vector<QRect> levelZero = levelZeroAreas(map, written);
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    labelGlObject(GlLabelKind::Framebuffer, m_framebuffer.id(), QStringLiteral("depth range pass"));
    m_gl->glBindVertexArray(m_emptyVertexArray.id());
    m_gl->glActiveTexture(GL_TEXTURE0 + kSourceUnit);

    for (int level = 0; level < levels(); ++level) {
        const QSize size = levelSize(level);
        if (level == 0)
            m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_atlas.id(), 0);
        else
            m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_chain.id(), level - 1);
        if (level <= 1) {
            const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE)
                throw RenderError(QStringLiteral("the min/max depth mip's framebuffer is incomplete (status 0x%1)").arg(status, 0, 16));
        }
        PassState state;
        state.viewport = QRect(QPoint(0, 0), size);
        applyPassState(m_gl, state);
        Program& p = level == 0 ? *m_fromDepth : *m_fromRange;
        p.program.bind();
        p.program.set(p.source, int(kSourceUnit));
        const QSize source = level == 0 ? mapSize : levelSize(level - 1);
        m_gl->glUniform2i(p.sourceSize, source.width(), source.height());
        if (level == 0)
            p.program.set(p.shadowSlice, map.slice().uniform());
        if (level == 0 && m_contents == Contents::Written)
            p.program.set(p.empty, reversedDepth ? 0.0f : 1.0f);
        if (level == 0) {
            m_gl->glBindTexture(GL_TEXTURE_2D, map.texture());
            m_gl->glBindSampler(kSourceUnit, map.sampler(ShadowSampler::RawNearest));
        } else if (level == 1) {
            m_gl->glBindTexture(GL_TEXTURE_2D, m_atlas.id());   // level 0, at the atlas's origin
            m_gl->glBindSampler(kSourceUnit, 0);
        } else {
            // Only the level read is in the chain's range while the next one is drawn: no
            // feedback loop through the attached level.
            m_gl->glBindTexture(GL_TEXTURE_2D, m_chain.id());
            m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 2);
            m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 2);
        }
        if (level > 0) {
            m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
            continue;
        }
        m_levelZeroDrawn = 0;
        m_gl->glEnable(GL_SCISSOR_TEST);
        for (const QRect& area : levelZero) {
            if (area.isEmpty())
                continue;
            m_gl->glScissor(area.x(), area.y(), area.width(), area.height());
            m_gl->glDrawArrays(GL_TRIANGLES, 0, 3);
            m_levelZeroDrawn += qint64(area.width()) * area.height();
        }
        m_gl->glDisable(GL_SCISSOR_TEST);
    }

    copyIntoAtlas();
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindSampler(kSourceUnit, 0);
    m_gl->glBindVertexArray(0);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
}

void DepthRangePass::copyIntoAtlas()
{
    if (levels() > 1) {
        m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_atlasFramebuffer.id());
        labelGlObject(GlLabelKind::Framebuffer, m_atlasFramebuffer.id(), QStringLiteral("depth range atlas"));
        m_gl->glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_atlas.id(), 0);
        m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
        for (int level = 1; level < levels(); ++level) {
            m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_chain.id(), level - 1);
            const QSize size = levelSize(level);
            const QPoint at = levelOrigin(level);
            m_gl->glBlitFramebuffer(0, 0, size.width(), size.height(), at.x(), at.y(), at.x() + size.width(), at.y() + size.height(),
                                    GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
        m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }
}

std::optional<std::pair<float, float>> DepthRangePass::readTotal()
{
    if (!m_atlas || levels() < 1)
        return std::nullopt;
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_atlasFramebuffer.id());
    m_gl->glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_atlas.id(), 0);
    const QPoint top = levelOrigin(levels() - 1);
    float range[2] = {0.0f, 0.0f};
    m_gl->glReadPixels(top.x(), top.y(), 1, 1, GL_RG, GL_FLOAT, range);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    if (!(range[0] <= range[1]))
        return std::nullopt;    // the neutral (1e30, -1e30): nothing written
    return std::pair{range[0], range[1]};
}

} // namespace shadowlab
