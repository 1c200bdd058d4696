#pragma once

#include "GlObject.h"
#include "Settings.h"
#include "ShadowTechnique.h"

namespace shadowlab {

// The light's depth texture and the framebuffer that renders into it. Border-clamped with a
// border depth at the far end (1.0, or 0.0 with reversed depth, which also compares GEQUAL),
// so lookups outside the map compare as lit. Three sampler objects
// read the same texture, one per ShadowSampler a technique may ask for: comparison nearest,
// comparison linear, and raw depth (nearest).
class ShadowMap {
public:
    explicit ShadowMap(GlFunctions* gl);

    // (Re)allocates when size or format differ. Throws SettingsError when the size exceeds the
    // driver's GL_MAX_TEXTURE_SIZE and RenderError when the driver cannot allocate it or the
    // framebuffer is incomplete; the previous map is kept then.
    void ensure(int size, DepthFormat format, bool reversedDepth = false);
    // The same for `columns` x `rows` tiles of size² texels side by side (cascades, cube faces).
    void ensureTiles(int size, int columns, int rows, DepthFormat format, bool reversedDepth = false);

    int size() const { return m_size; }             // texels per side of one tile (of the map, with one tile)
    int width() const { return m_size * m_columns; }
    int height() const { return m_size * m_rows; }
    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    DepthFormat format() const { return m_format; }
    bool reversedDepth() const { return m_reversedDepth; }
    GLuint texture() const { return m_texture.id(); }
    GLuint framebuffer() const { return m_framebuffer.id(); }
    // The sampler object a technique's row asks for (ShadowTechnique::samplers).
    GLuint sampler(ShadowSampler kind) const;

private:
    void allocate(int size, int columns, int rows, DepthFormat format);

    GlFunctions* m_gl;
    GlTexture m_texture;
    GlFramebuffer m_framebuffer;
    GlSampler m_compareNearest;
    GlSampler m_compareLinear;
    GlSampler m_raw;
    int m_size = 0;
    int m_columns = 1;
    int m_rows = 1;
    DepthFormat m_format = DepthFormat::Depth24;
    bool m_reversedDepth = false;
};

} // namespace shadowlab
