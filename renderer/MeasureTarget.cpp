#include "MeasureTarget.h"

#include "RenderError.h"

#include <algorithm>

namespace shadowlab {

namespace {

GlTexture makeAttachment(GlFunctions* gl, GLenum internalFormat, GLenum format, GLenum type, QSize size, const char* name)
{
    GlTexture texture = makeTexture(gl);
    gl->glBindTexture(GL_TEXTURE_2D, texture.id());
    labelGlObject(GlLabelKind::Texture, texture.id(), QStringLiteral("measurement: %1").arg(QLatin1String(name)));
    gl->glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), size.width(), size.height(), 0, format, type, nullptr);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

template <typename T>
void flipRows(std::vector<T>& pixels, int width, int height)
{
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(y) * width, pixels.begin() + std::ptrdiff_t(y + 1) * width,
                         pixels.begin() + std::ptrdiff_t(height - 1 - y) * width);
}

} // namespace

MeasureTarget::MeasureTarget(GlFunctions* gl) : m_gl(gl) {}

RenderTarget MeasureTarget::ensure(QSize size)
{
    if (!(m_current.framebuffer && m_current.size == size)) {
        Attachments next = m_before.framebuffer && m_before.size == size ? std::move(m_before) : allocate(size);
        m_before = std::move(m_current);
        m_current = std::move(next);
    }
    return {m_current.framebuffer.id(), m_current.size};
}

MeasureTarget::Attachments MeasureTarget::allocate(QSize size) const
{
    Attachments a;
    a.size = size;
    a.framebuffer = makeFramebuffer(m_gl);
    a.color = makeAttachment(m_gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, size, "colour");
    a.position = makeAttachment(m_gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, size, "position, visibility");
    a.normal = makeAttachment(m_gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, size, "normal, mask");
    a.ambient = makeAttachment(m_gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, size, "ambient light");
    a.direct = makeAttachment(m_gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, size, "direct light");
    // With stencil: the lit pass masks where a shadow lookup can find a caster (core/ShadowReach.h).
    a.depth = makeAttachment(m_gl, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, size, "depth, stencil");
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, a.framebuffer.id());
    labelGlObject(GlLabelKind::Framebuffer, a.framebuffer.id(), QStringLiteral("measurement"));
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, a.color.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, a.position.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, a.normal.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, a.ambient.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT4, GL_TEXTURE_2D, a.direct.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, a.depth.id(), 0);
    const GLenum buffers[5] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
    m_gl->glDrawBuffers(5, buffers);
    const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the %1x%2 measurement framebuffer is incomplete (status 0x%3)")
                              .arg(size.width())
                              .arg(size.height())
                              .arg(status, 0, 16));
    return a;
}

VisibilityBuffer MeasureTarget::read(const glm::dvec3& cameraPosition) const
{
    const QSize size = m_current.size;
    VisibilityBuffer b;
    b.size = size;
    b.cameraPosition = cameraPosition;
    const int w = size.width(), h = size.height();
    b.positionVisibility.resize(std::size_t(w) * std::size_t(h));
    b.normalMask.resize(b.positionVisibility.size());
    b.ambientLight.resize(b.positionVisibility.size());
    b.directLight.resize(b.positionVisibility.size());
    b.image = QImage(size, QImage::Format_RGBA8888);

    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, m_current.framebuffer.id());
    m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    m_gl->glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, b.image.bits());
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT1);
    m_gl->glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, b.positionVisibility.data());
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT2);
    m_gl->glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, b.normalMask.data());
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT3);
    m_gl->glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, b.ambientLight.data());
    m_gl->glReadBuffer(GL_COLOR_ATTACHMENT4);
    m_gl->glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, b.directLight.data());
    m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);

    // GL rows run bottom to top; images and everything else here run top to bottom.
    b.image = b.image.mirrored(false, true).convertToFormat(QImage::Format_RGB32);
    flipRows(b.positionVisibility, w, h);
    flipRows(b.normalMask, w, h);
    flipRows(b.ambientLight, w, h);
    flipRows(b.directLight, w, h);
    return b;
}

} // namespace shadowlab
