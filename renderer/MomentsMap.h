#pragma once

#include "GlObject.h"
#include "Settings.h"
#include "WrittenTexels.h"

#include <QString>

namespace shadowlab {

// The moments texture of the moment techniques (vsm, evsm, msm, esm) and what renders into it:
// a colour texture of the technique's one, two or four channels (R, RG or RGBA; three take
// RGBA), 16- or 32-bit float, with a depth texture for the moments pass, a second colour texture
// of the same format for the blur pass's first axis (only while a blur pass runs), and the
// filtered sampler the lit pass reads it through (bilinear; trilinear with mipmaps; anisotropic
// where asked and offered).
class MomentsMap {
public:
    explicit MomentsMap(GlFunctions* gl);

    // (Re)allocates when size, tiles, format or mipmaps differ and sets the sampler's
    // anisotropy. `columns` x `rows` tiles of `size` texels side by side hold several views
    // (cascades, cube faces), as ShadowMap's tiles do. The blur's scratch texture exists while
    // `blurPass` says a blur pass runs (moments.blur_at). Throws SettingsError when the texture
    // would exceed GL_MAX_TEXTURE_SIZE and RenderError when the driver cannot allocate or render
    // to it; the previous map is kept then.
    void ensureTiles(int size, int columns, int rows, MomentFormat format, int channels, bool mipmaps, int anisotropy, bool blurPass);

    int size() const { return m_size; }             // texels per side of one tile
    int width() const { return m_size * m_columns; }
    int height() const { return m_size * m_rows; }
    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    MomentFormat format() const { return m_format; }
    int channels() const { return m_channels; }
    // Its memory in bytes with `channels` a texel: the moments with their mips, the pass's depth
    // and the blur's scratch where it exists.
    qint64 bytes(int channels) const;
    // Which texels draws since their clear may have written (the far plane's moments elsewhere).
    WrittenTexels& written() { return m_written; }
    // What the far plane's moments are, named by the encoding that made them (the technique,
    // format and exponents: MomentsPass). Another name: every texel counts as written, since
    // the old far plane reads wrong in the new encoding (vsm's (1, 1) is shadow to evsm2).
    void encodedBy(const QString& encoding)
    {
        if (encoding != m_encoding)
            m_written.reset(m_size, m_columns, m_rows);
        m_encoding = encoding;
    }
    bool mipmaps() const { return m_mipmaps; }
    // The anisotropy the sampler uses: the setting capped by the driver's maximum (1 without
    // the extension).
    GLuint texture() const { return m_texture.id(); }
    GLuint depthTexture() const { return m_depth.id(); }
    GLuint framebuffer() const { return m_framebuffer.id(); }
    // The blur's intermediate target (first axis), and its framebuffer: 0 while no blur pass runs.
    GLuint scratchTexture() const { return m_scratch.id(); }
    GLuint scratchFramebuffer() const { return m_scratchFramebuffer.id(); }
    GLuint sampler() const { return m_sampler.id(); }

private:
    void allocate(int size, int columns, int rows, MomentFormat format, int channels, bool mipmaps);
    void configureSampler(bool mipmaps, float anisotropy);
    // Makes the blur's scratch texture and framebuffer where `wanted`, frees them where not.
    void ensureScratch(bool wanted);

    GlFunctions* m_gl;
    GlTexture m_texture;
    GlTexture m_depth;
    GlTexture m_scratch;
    GlFramebuffer m_framebuffer;
    GlFramebuffer m_scratchFramebuffer;
    GlSampler m_sampler;
    int m_size = 0;
    int m_columns = 1;
    int m_rows = 1;
    MomentFormat m_format = MomentFormat::Rgba32F;
    int m_channels = 4;
    WrittenTexels m_written;
    QString m_encoding;
    bool m_mipmaps = false;
    float m_anisotropy = 1.0f;
    float m_maxAnisotropy = 1.0f;   // the driver's; 1 without anisotropic filtering
};

} // namespace shadowlab
