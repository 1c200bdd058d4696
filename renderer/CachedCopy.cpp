#include "CachedCopy.h"

#include "RenderError.h"

namespace shadowlab {

namespace {

GLint internalFormatOf(GlFunctions* gl, GLuint texture)
{
    if (!texture)
        return 0;
    GLint format = 0, bound = 0;
    gl->glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    gl->glBindTexture(GL_TEXTURE_2D, texture);
    gl->glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    gl->glBindTexture(GL_TEXTURE_2D, GLuint(bound));
    return format;
}

// Bytes a texel of the formats a shadow storage uses.
int texelBytes(GLint format)
{
    switch (format) {
    case 0:
        return 0;
    case GL_R16F:
        return 2;
    case GL_RG16F:
        return 4;
    case GL_RGBA16F:
    case GL_RG32F:
        return 8;
    case GL_RGBA32F:
        return 16;
    default:
        return 4;   // depth24 (stored in 32 bits), depth32f, r32f
    }
}

} // namespace

void CachedCopy::ensure(QSize size, GLuint depth, GLuint colour, const QString& label)
{
    const GLint depthFormat = internalFormatOf(m_gl, depth);
    const GLint colourFormat = internalFormatOf(m_gl, colour);
    if (m_framebuffer && size == m_size && depthFormat == m_depthFormat && colourFormat == m_colourFormat)
        return;
    release();
    while (m_gl->glGetError() != GL_NO_ERROR) {
    }
    const auto texture = [&](GLint format, GLenum pixelFormat, GLenum type, const QString& label) {
        GlTexture t = makeTexture(m_gl);
        m_gl->glBindTexture(GL_TEXTURE_2D, t.id());
        m_gl->glTexImage2D(GL_TEXTURE_2D, 0, format, size.width(), size.height(), 0, pixelFormat, type, nullptr);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        labelGlObject(GlLabelKind::Texture, t.id(), label);
        return t;
    };
    if (depthFormat)
        m_depth = texture(depthFormat, GL_DEPTH_COMPONENT, GL_FLOAT, label + QStringLiteral(": depth"));
    if (colourFormat) {
        const bool integer = colourFormat == GL_R32UI || colourFormat == GL_R16UI || colourFormat == GL_R8UI;
        m_colour = texture(colourFormat, integer ? GL_RED_INTEGER : GL_RGBA, integer ? GL_UNSIGNED_INT : GL_FLOAT, label + QStringLiteral(": colour"));
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    m_framebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    if (m_depth)
        m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
    if (m_colour) {
        m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_colour.id(), 0);
    } else {
        m_gl->glDrawBuffer(GL_NONE);
        m_gl->glReadBuffer(GL_NONE);
    }
    const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    labelGlObject(GlLabelKind::Framebuffer, m_framebuffer.id(), label);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    const GLenum error = m_gl->glGetError();
    if (status != GL_FRAMEBUFFER_COMPLETE || error != GL_NO_ERROR) {
        release();
        throw RenderError(QStringLiteral("the driver cannot keep a %1 x %2 copy for the %3 (status 0x%4, GL error 0x%5); choose a smaller "
                                         "map.size or window, or shadow.cache=off")
                              .arg(size.width()).arg(size.height()).arg(label).arg(status, 0, 16).arg(error, 0, 16));
    }
    m_size = size;
    m_depthFormat = depthFormat;
    m_colourFormat = colourFormat;
    m_bytes = qint64(size.width()) * size.height() * (texelBytes(depthFormat) + texelBytes(colourFormat));
}

void CachedCopy::release()
{
    m_framebuffer.reset();
    m_depth.reset();
    m_colour.reset();
    m_size = {};
    m_depthFormat = m_colourFormat = 0;
    m_bytes = 0;
}

void CachedCopy::save(GLuint framebuffer, const QRect& rect)
{
    blit(framebuffer, m_framebuffer.id(), rect);
}

void CachedCopy::restore(GLuint framebuffer, const QRect& rect)
{
    blit(m_framebuffer.id(), framebuffer, rect);
}

void CachedCopy::blit(GLuint from, GLuint to, const QRect& rect)
{
    GLint previousRead = 0, previousDraw = 0;
    m_gl->glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    const GLbitfield bits = (m_depth ? GL_DEPTH_BUFFER_BIT : 0u) | (m_colour ? GL_COLOR_BUFFER_BIT : 0u);
    const int x1 = rect.x() + rect.width(), y1 = rect.y() + rect.height();
    // Nothing may clip or mask a copy: it restores every texel as it was. (The passes set their
    // masks; the scissor is put back.)
    const GLboolean scissor = m_gl->glIsEnabled(GL_SCISSOR_TEST);
    m_gl->glDisable(GL_SCISSOR_TEST);
    m_gl->glDepthMask(GL_TRUE);
    m_gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    m_gl->glBlitFramebuffer(rect.x(), rect.y(), x1, y1, rect.x(), rect.y(), x1, y1, bits, GL_NEAREST);
    if (scissor)
        m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousDraw));
}

} // namespace shadowlab
