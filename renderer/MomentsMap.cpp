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

void MomentsMap::ensureTiles(int size, int columns, int rows, MomentFormat format, int channels, bool mipmaps, int anisotropy)
{
    channels = channels == 1 || channels == 2 ? channels : 4;
    if (!m_texture || size != m_size || columns != m_columns || rows != m_rows || format != m_format || channels != m_channels || mipmaps != m_mipmaps)
        allocate(size, columns, rows, format, channels, mipmaps);
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
    auto colour = [&](const QString& label, int levels) {
        GlTexture texture = makeTexture(m_gl);
        m_gl->glBindTexture(GL_TEXTURE_2D, texture.id());
        for (int level = 0, w = width, h = height; level < levels; ++level, w = std::max(1, w / 2), h = std::max(1, h / 2))
            m_gl->glTexImage2D(GL_TEXTURE_2D, level, GLint(internalFormat(format, channels)), w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
        labelGlObject(GlLabelKind::Texture, texture.id(), label);
        return texture;
    };
    GlTexture texture = colour(what, mipmaps ? mipLevels(std::max(width, height)) : 1);
    GlTexture scratch = colour(QStringLiteral("moments blur: first axis"), 1);
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

    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    auto framebufferFor = [&](GLuint colourTexture, GLuint depthTexture, const QString& label) {
        GlFramebuffer framebuffer = makeFramebuffer(m_gl);
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colourTexture, 0);
        if (depthTexture)
            m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture, 0);
        const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
        labelGlObject(GlLabelKind::Framebuffer, framebuffer.id(), label);
        m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw RenderError(QStringLiteral("the %1's framebuffer is incomplete (status 0x%2); try moments.format=%3")
                                  .arg(what)
                                  .arg(status, 0, 16)
                                  .arg(format == MomentFormat::Rgba16F ? 32 : 16));
        return framebuffer;
    };
    GlFramebuffer framebuffer = framebufferFor(texture.id(), depth.id(), QStringLiteral("moments pass"));
    GlFramebuffer scratchFramebuffer = framebufferFor(scratch.id(), 0, QStringLiteral("moments blur: first axis"));

    m_texture = std::move(texture);
    m_depth = std::move(depth);
    m_scratch = std::move(scratch);
    m_framebuffer = std::move(framebuffer);
    m_scratchFramebuffer = std::move(scratchFramebuffer);
    m_size = size;
    m_columns = columns;
    m_rows = rows;
    m_format = format;
    m_channels = channels;
    m_written.reset(size, columns, rows);
}

qint64 MomentsMap::bytes(int channels) const
{
    const qint64 texel = qint64(channels) * (m_format == MomentFormat::Rgba16F ? 2 : 4);
    qint64 colour = qint64(width()) * height() * texel;
    if (m_mipmaps)
        colour += colour / 3;
    // The blur's scratch texture and the pass's 24-bit depth (stored in 32 bits).
    return colour + qint64(width()) * height() * (texel + 4);
}

} // namespace shadowlab
