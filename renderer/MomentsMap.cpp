#include "MomentsMap.h"

#include "RenderError.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QOpenGLContext>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// GL_EXT_texture_filter_anisotropic / GL 4.6 (not in the 3.3 headers' core names).
constexpr GLenum kTextureMaxAnisotropy = 0x84FE;
constexpr GLenum kMaxTextureMaxAnisotropy = 0x84FF;

// One, two or four channels, as the technique stores (ShadowTechnique::momentChannels).
GLenum internalFormat(MomentFormat format, int channels)
{
    const bool half = format == MomentFormat::Rgba16F;
    if (channels == 1)
        return half ? GL_R16F : GL_R32F;
    if (channels == 2)
        return half ? GL_RG16F : GL_RG32F;
    return half ? GL_RGBA16F : GL_RGBA32F;
}

QString formatName(MomentFormat format, int channels)
{
    return QStringLiteral("%1%2F").arg(channels == 1 ? QStringLiteral("R") : channels == 2 ? QStringLiteral("RG") : QStringLiteral("RGBA")).arg(toString(format));
}

int mipLevels(int size)
{
    return int(std::floor(std::log2(double(size)))) + 1;
}

// A colour texture of `levels` levels in the map's format, sampled nearest (the lit pass's
// filtered reads go through MomentsMap's own sampler).
GlTexture colourTexture(GlFunctions* gl, int width, int height, MomentFormat format, int channels, const QString& label, int levels)
{
    GlTexture texture = makeTexture(gl);
    gl->glBindTexture(GL_TEXTURE_2D, texture.id());
    for (int level = 0, w = width, h = height; level < levels; ++level, w = std::max(1, w / 2), h = std::max(1, h / 2))
        gl->glTexImage2D(GL_TEXTURE_2D, level, GLint(internalFormat(format, channels)), w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    labelGlObject(GlLabelKind::Texture, texture.id(), label);
    gl->glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

// A framebuffer of `colour` (and `depth`, where not 0); throws RenderError, naming `what`, where
// the driver cannot render to it.
GlFramebuffer framebufferFor(GlFunctions* gl, GLuint colour, GLuint depth, const QString& label, const QString& what, MomentFormat format)
{
    GLint previous = 0;
    gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    GlFramebuffer framebuffer = makeFramebuffer(gl);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    if (depth)
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    const GLenum status = gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    labelGlObject(GlLabelKind::Framebuffer, framebuffer.id(), label);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the %1's framebuffer is incomplete (status 0x%2); try moments.format=%3")
                              .arg(what)
                              .arg(status, 0, 16)
                              .arg(format == MomentFormat::Rgba16F ? 32 : 16));
    return framebuffer;
}

} // namespace

MomentsMap::MomentsMap(GlFunctions* gl) : m_gl(gl), m_sampler(makeSampler(gl))
{
    const QOpenGLContext* context = QOpenGLContext::currentContext();
    if (context && (context->hasExtension("GL_EXT_texture_filter_anisotropic") || context->hasExtension("GL_ARB_texture_filter_anisotropic"))) {
        GLfloat largest = 1.0f;
        m_gl->glGetFloatv(kMaxTextureMaxAnisotropy, &largest);
        m_maxAnisotropy = std::max(1.0f, largest);
    }
    configureSampler(false, 1.0f);
    labelGlObject(GlLabelKind::Sampler, m_sampler.id(), QStringLiteral("moments map: filtered"));
}

void MomentsMap::configureSampler(bool mipmaps, float anisotropy)
{
    const GLuint s = m_sampler.id();
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Lookups outside the map are answered "lit" by the technique before they sample.
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    m_gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (m_maxAnisotropy > 1.0f)
        m_gl->glSamplerParameterf(s, kTextureMaxAnisotropy, anisotropy);
    m_anisotropy = anisotropy;
}

void MomentsMap::ensureTiles(int size, int columns, int rows, MomentFormat format, int channels, bool mipmaps, int anisotropy, bool blurPass)
{
    channels = channels == 1 || channels == 2 ? channels : 4;
    if (!m_texture || size != m_size || columns != m_columns || rows != m_rows || format != m_format || channels != m_channels || mipmaps != m_mipmaps)
        allocate(size, columns, rows, format, channels, mipmaps);
    ensureScratch(blurPass);
    const float wanted = std::min(float(anisotropy), m_maxAnisotropy);
    if (wanted != m_anisotropy || mipmaps != m_mipmaps)
        configureSampler(mipmaps, wanted);
    m_mipmaps = mipmaps;
}

void MomentsMap::allocate(int size, int columns, int rows, MomentFormat format, int channels, bool mipmaps)
{
    GLint maxSize = 0;
    m_gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const int width = size * columns, height = size * rows;
    if (size < 16 || width > maxSize || height > maxSize)
        throw SettingsError(QStringLiteral("map.size"),
                            columns * rows > 1 ? QStringLiteral("%1 is out of range for %2 x %3 tiles; this driver allows [16, %4]")
                                                     .arg(size).arg(columns).arg(rows).arg(maxSize / std::max(columns, rows))
                                               : QStringLiteral("%1 is out of range; this driver allows [16, %2]").arg(size).arg(maxSize));
    const QString what = QStringLiteral("%1 x %2 %3 moments map").arg(width).arg(height).arg(formatName(format, channels));

    while (m_gl->glGetError() != GL_NO_ERROR) {
    }
    GlTexture texture = colourTexture(m_gl, width, height, format, channels, what, mipmaps ? mipLevels(std::max(width, height)) : 1);
    GlTexture depth = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, depth.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    labelGlObject(GlLabelKind::Texture, depth.id(), QStringLiteral("moments pass: depth"));
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    if (const GLenum error = m_gl->glGetError(); error != GL_NO_ERROR) {
        throw RenderError(QStringLiteral("the driver cannot allocate a %1 (GL error 0x%2); choose a smaller map.size or moments.format=16")
                              .arg(what)
                              .arg(error, 0, 16));
    }

    GlFramebuffer framebuffer = framebufferFor(m_gl, texture.id(), depth.id(), QStringLiteral("moments pass"), what, format);

    m_texture = std::move(texture);
    m_depth = std::move(depth);
    m_framebuffer = std::move(framebuffer);
    m_scratchFramebuffer = GlFramebuffer();     // the old size's; ensureScratch() makes one
    m_scratch = GlTexture();
    m_size = size;
    m_columns = columns;
    m_rows = rows;
    m_format = format;
    m_channels = channels;
    m_written.reset(size, columns, rows);
}

void MomentsMap::ensureScratch(bool wanted)
{
    if (!wanted) {
        m_scratchFramebuffer = GlFramebuffer();
        m_scratch = GlTexture();
        return;
    }
    if (m_scratch)
        return;
    while (m_gl->glGetError() != GL_NO_ERROR) {
    }
    const QString what = QStringLiteral("%1 x %2 %3 moments blur target").arg(width()).arg(height()).arg(formatName(m_format, m_channels));
    GlTexture scratch = colourTexture(m_gl, width(), height(), m_format, m_channels, QStringLiteral("moments blur: first axis"), 1);
    if (const GLenum error = m_gl->glGetError(); error != GL_NO_ERROR)
        throw RenderError(QStringLiteral("the driver cannot allocate a %1 (GL error 0x%2); choose a smaller map.size, moments.format=16 or "
                                         "moments.blur_at=lookup")
                              .arg(what)
                              .arg(error, 0, 16));
    m_scratchFramebuffer = framebufferFor(m_gl, scratch.id(), 0, QStringLiteral("moments blur: first axis"), what, m_format);
    m_scratch = std::move(scratch);
}

qint64 MomentsMap::bytes(int channels) const
{
    const qint64 texel = qint64(channels) * (m_format == MomentFormat::Rgba16F ? 2 : 4);
    qint64 colour = qint64(width()) * height() * texel;
    if (m_mipmaps)
        colour += colour / 3;
    // The pass's 24-bit depth (stored in 32 bits), and the blur's scratch texture where a blur
    // pass runs.
    return colour + qint64(width()) * height() * ((m_scratch ? texel : 0) + 4);
}

} // namespace shadowlab
