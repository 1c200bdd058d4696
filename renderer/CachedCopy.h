#pragma once

#include "GlObject.h"

#include <QRect>
#include <QString>
#include <QSize>

namespace shadowlab {

// A copy of a render target, texel for texel: what shadow.cache keeps of the still casters
// (renderer/ShadowCache.h), and of the still objects' page requests (VirtualShadowMap). Its
// textures take the internal formats of the source's, so glBlitFramebuffer copies them
// exactly, depth and colour (float or integer) alike (GL 3.3 core).
class CachedCopy {
public:
    explicit CachedCopy(GlFunctions* gl) : m_gl(gl) {}

    // Textures of the formats and size of `depth` and `colour` (0: none), reallocated when they
    // change. Throws RenderError when the driver cannot allocate them or render to them.
    // `label` names them in a debugger's list.
    void ensure(QSize size, GLuint depth, GLuint colour, const QString& label = QStringLiteral("shadow cache"));
    // Copies `rect` (texels) of `framebuffer`'s attachments into the copy, and back.
    void save(GLuint framebuffer, const QRect& rect);
    void restore(GLuint framebuffer, const QRect& rect);
    // Drops the textures (a policy without copies).
    void release();
    qint64 bytes() const { return m_bytes; }

private:
    void blit(GLuint from, GLuint to, const QRect& rect);

    GlFunctions* m_gl;
    GlTexture m_depth;
    GlTexture m_colour;
    GlFramebuffer m_framebuffer;
    QSize m_size;
    GLint m_depthFormat = 0;
    GLint m_colourFormat = 0;
    qint64 m_bytes = 0;
};

} // namespace shadowlab
