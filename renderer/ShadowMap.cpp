#include "ShadowMap.h"

#include "RenderError.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <algorithm>
#include <utility>

namespace shadowlab {

namespace {

void configureSampler(GlFunctions* gl, GLuint sampler, GLint filter, bool compare, bool reversedDepth)
{
    const GLfloat far = reversedDepth ? 0.0f : 1.0f;
    const GLfloat border[4] = {far, far, far, far};
    gl->glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, filter);
    gl->glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, filter);
    gl->glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    gl->glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    gl->glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, border);
    gl->glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    gl->glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, reversedDepth ? GL_GEQUAL : GL_LEQUAL);
}

} // namespace

ShadowMap::ShadowMap(GlFunctions* gl)
    : m_gl(gl), m_compareNearest(makeSampler(gl)), m_compareLinear(makeSampler(gl)), m_raw(makeSampler(gl))
{
    configureSampler(gl, m_compareNearest.id(), GL_NEAREST, true, false);
    configureSampler(gl, m_compareLinear.id(), GL_LINEAR, true, false);
    configureSampler(gl, m_raw.id(), GL_NEAREST, false, false);
    labelGlObject(GlLabelKind::Sampler, m_compareNearest.id(), QStringLiteral("shadow map: compare nearest"));
    labelGlObject(GlLabelKind::Sampler, m_compareLinear.id(), QStringLiteral("shadow map: compare linear"));
    labelGlObject(GlLabelKind::Sampler, m_raw.id(), QStringLiteral("shadow map: raw depth"));
}

void ShadowMap::ensure(int size, DepthFormat format, bool reversedDepth)
{
    ensureTiles(size, 1, 1, format, reversedDepth);
}

void ShadowMap::ensureTiles(int size, int columns, int rows, DepthFormat format, bool reversedDepth)
{
    if (!m_texture || size != m_size || columns != m_columns || rows != m_rows || format != m_format)
        allocate(size, columns, rows, format);
    if (reversedDepth != m_reversedDepth) {
        configureSampler(m_gl, m_compareNearest.id(), GL_NEAREST, true, reversedDepth);
        configureSampler(m_gl, m_compareLinear.id(), GL_LINEAR, true, reversedDepth);
        configureSampler(m_gl, m_raw.id(), GL_NEAREST, false, reversedDepth);
        m_reversedDepth = reversedDepth;
        m_written.reset(m_size, m_columns, m_rows);    // its far depth is now near
        m_slices.reset();
        m_pass = {};
    }
}

DepthSlices::Draw ShadowMap::beginDraw(const QRect& tile, int slices)
{
    const bool tiles = m_columns * m_rows > 1;
    const bool sliceable = tile == QRect(0, 0, width(), height()) && ShadowMap::slices(slices, m_format, m_reversedDepth);
    const DepthSlices::Draw draw = tiles ? m_pass : m_slices.beginDraw(slices, sliceable);
    m_clearCount += draw.clear;
    return draw;
}

void ShadowMap::beginPass(int slices)
{
    if (m_columns * m_rows > 1)
        m_pass = m_slices.beginDraw(slices, ShadowMap::slices(slices, m_format, m_reversedDepth));
}

void ShadowMap::cleared(const QRect& tile)
{
    m_written.cleared(tile);
    const bool whole = tile == QRect(0, 0, width(), height());
    if (whole || m_columns * m_rows == 1)
        m_slices.cleared(whole);
    ++m_clearCount;
}

GLuint ShadowMap::sampler(ShadowSampler kind) const
{
    switch (kind) {
    case ShadowSampler::CompareNearest:
        return m_compareNearest.id();
    case ShadowSampler::CompareLinear:
        return m_compareLinear.id();
    case ShadowSampler::RawNearest:
        return m_raw.id();
    case ShadowSampler::Moments:
        return 0;   // the moments map's own (MomentsMap::sampler())
    }
    return 0;
}

void ShadowMap::allocate(int size, int columns, int rows, DepthFormat format)
{
    GLint maxSize = 0;
    m_gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (size < 16 || size > maxSize)
        throw SettingsError(QStringLiteral("map.size"),
                            QStringLiteral("%1 is out of range; this driver allows [16, %2]").arg(size).arg(maxSize));
    const int width = size * columns, height = size * rows;
    if (width > maxSize || height > maxSize)
        throw SettingsError(QStringLiteral("map.size"),
                            QStringLiteral("%1 x %2 maps of %3 texels do not fit in one %4 x %5 texture (this driver allows %6 per side); "
                                           "choose map.size <= %7")
                                .arg(columns).arg(rows).arg(size).arg(width).arg(height).arg(maxSize).arg(maxSize / std::max(columns, rows)));

    while (m_gl->glGetError() != GL_NO_ERROR) {
    }
    GlTexture texture = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, texture.id());
    const bool float32 = format == DepthFormat::Depth32F;
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, float32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24, width, height, 0,
                       GL_DEPTH_COMPONENT, float32 ? GL_FLOAT : GL_UNSIGNED_INT, nullptr);
    // Texture parameters matter only to users that bind no sampler object (another context's view).
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    labelGlObject(GlLabelKind::Texture, texture.id(), QStringLiteral("shadow map %1 x %2 %3").arg(width).arg(height).arg(toString(format)));
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    if (const GLenum error = m_gl->glGetError(); error != GL_NO_ERROR) {
        throw RenderError(QStringLiteral("the driver cannot allocate a %1 x %1 %2 shadow map (GL error 0x%3); choose a smaller map.size")
                              .arg(size)
                              .arg(toString(format))
                              .arg(error, 0, 16));
    }

    GlFramebuffer framebuffer = makeFramebuffer(m_gl);
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture.id(), 0);
    m_gl->glDrawBuffer(GL_NONE);
    m_gl->glReadBuffer(GL_NONE);
    const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    labelGlObject(GlLabelKind::Framebuffer, framebuffer.id(), QStringLiteral("shadow pass"));
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw RenderError(QStringLiteral("the %1 x %1 %2 shadow-map framebuffer is incomplete (status 0x%3)")
                              .arg(size)
                              .arg(toString(format))
                              .arg(status, 0, 16));
    }
    m_texture = std::move(texture);
    m_framebuffer = std::move(framebuffer);
    m_size = size;
    m_columns = columns;
    m_rows = rows;
    m_format = format;
    m_written.reset(size, columns, rows);
    m_slices.reset();
    m_pass = {};
}

} // namespace shadowlab
