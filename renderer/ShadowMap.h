#pragma once

#include "DepthSlices.h"
#include "GlObject.h"
#include "Settings.h"
#include "ShadowTechnique.h"
#include "WrittenTexels.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <QRect>

#include <algorithm>

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

    // Depth slices (DepthSlices, map.slices): before a draw into `tile` (texels), whether to
    // clear it first and the slice to write; `slices` as the plan asks (FramePlan::slices). A
    // map of one view moves to its next slice with each draw; a map of several tiles with each
    // pass (beginPass), whose draws all write into that pass's slice.
    DepthSlices::Draw beginDraw(const QRect& tile, int slices);
    // Before the draws of a pass into a map of several tiles: the slice they write, or none
    // (`slices` 1: each draw clears its tile first). Every tile that holds casters must be drawn
    // in a sliced pass, as what earlier passes left reads beyond the far plane after it.
    void beginPass(int slices);
    DepthSlices& depthSlices() { return m_slices; }
    const DepthSlices& depthSlices() const { return m_slices; }
    // Where the last draw wrote: how lookups read the map now.
    const DepthSlice& slice() const { return m_slices.current(); }
    // Whether a draw asking for `slices` draws into slices: the lit pass's DEPTH_SLICES variant.
    static bool slices(int slices, DepthFormat format, bool reversedDepth) { return slices > 1 && format == DepthFormat::Depth24 && !reversedDepth; }
    // After a clear of `tile` (a whole tile, or the part of one WrittenTexels names). A cleared
    // texel reads beyond the far plane in any slice, so a clear of one tile of several leaves the
    // pass's slice as it is.
    void cleared(const QRect& tile);
    // Which texels draws since their clear may have written.
    WrittenTexels& written() { return m_written; }
    const WrittenTexels& written() const { return m_written; }
    // Clears of the map or of a tile so far, whether asked for or before a draw.
    int clearCount() const { return m_clearCount; }

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
    int m_clearCount = 0;
    DepthSlices m_slices;
    DepthSlices::Draw m_pass;       // a map of several tiles: the slice of this pass's draws
    WrittenTexels m_written;
};

} // namespace shadowlab
