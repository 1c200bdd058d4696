#pragma once

#include "GlObject.h"
#include "Settings.h"
#include "ShadowTechnique.h"
#include "WrittenTexels.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <QRect>

#include <algorithm>

namespace shadowlab {

// Where in the depth buffer's [0, 1] a draw of the map wrote its conventional depth d (0 at the
// light's near plane, 1 at its far plane): stored = offset + d * scale. Above offset + scale
// lies a gap, then what earlier draws left (ShadowMap::beginDraw): from `emptyFrom` up a
// stored value reads as the far plane, as a cleared texel does.
struct DepthSlice {
    // Between slices: 16 steps of a 24-bit depth, so no value rounds into its neighbour's.
    static constexpr double kGap = 1.0 / (1 << 20);

    double offset = 0.0;
    double scale = 1.0;
    double emptyFrom = 1.0;

    double stored(double depth) const { return offset + depth * scale; }
    // A stored value as conventional depth, at most 1 (shaders/depth_slice.glsl).
    double depth(double storedValue) const { return storedValue >= emptyFrom ? 1.0 : std::min((storedValue - offset) / scale, 1.0); }
    // For the shaders' uShadowSlice.
    glm::vec3 uniform() const { return {float(offset), float(scale), float(emptyFrom)}; }
    // Conventional depth to stored, on homogeneous coordinates: folded into the lit pass's
    // shadow matrix, so its lookups compare in stored depth with no work per tap.
    glm::dmat4 matrix() const
    {
        glm::dmat4 m(1.0);
        m[2][2] = scale;
        m[3][2] = offset;
        return m;
    }
    bool operator==(const DepthSlice&) const = default;
};

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

    // Depth slices (map.slices = n): a clear writes every texel, which costs a software
    // rasteriser as much as the casters do. A map of one 24-bit view is instead cleared once in
    // n draws: draw k after a clear writes its depth into the k-th slice of [0, 1] from the top,
    // 1/n wide less a gap at its top, nearer than every slice before it, so what the earlier
    // draws left compares as beyond the far plane, lit, exactly as a cleared texel does. It
    // costs log2(n) bits of the 24. Maps of several tiles (cascades, cube faces, virtual pages)
    // and reversed (float) depth, whose precision lies near 0, clear every draw, and so do
    // perspective maps (core's slicesDepth).
    struct Draw {
        bool clear = true;          // clear the tile before drawing
        DepthSlice slice;           // where the draw writes
    };
    // Before a draw into `tile` (texels): whether to clear it first, and the slice to write.
    Draw beginDraw(const QRect& tile, int slices);
    // The share of the map the next draw's casters may cover (the area of their reach boxes,
    // ShadowReach, which bound their footprints). A draw into a slice reads each texel its
    // casters cover from memory, where after a clear it finds it in the cache, so a draw whose
    // boxes cover more than kSlicedCoverage clears (docs/performance.md has the figures).
    void setCasterCoverage(double share) { m_casterCoverage = share; }
    double casterCoverage() const { return m_casterCoverage; }
    static constexpr double kSlicedCoverage = 0.85;
    // Tests: slice whatever the coverage (1), or at the default.
    void setSlicedCoverageLimit(double limit) { m_slicedCoverageLimit = limit; }
    // After a clear of `tile` (a whole tile, or the part of one WrittenTexels names).
    void cleared(const QRect& tile);
    // Which texels draws since their clear may have written.
    WrittenTexels& written() { return m_written; }
    // Where the last draw wrote: how lookups read the map now, and which slice since the last
    // clear that is (0: the first, or not sliced).
    DepthSlice slice() const { return m_slice; }
    int sliceIndex() const { return m_slice.scale < 1.0 ? m_drawsSinceClear - 1 : 0; }
    // The next draw clears and starts again at the first slice.
    void restartSlices() { m_restart = true; }
    // Clears of the map or of a tile so far, whether asked for or before a draw.
    int clearCount() const { return m_clearCount; }
    // Whether a draw asking for `slices` (FramePlan::slices, core's slicesDepth) draws into
    // slices: the lit pass's DEPTH_SLICES variant.
    static bool slices(int slices, DepthFormat format, bool reversedDepth) { return slices > 1 && format == DepthFormat::Depth24 && !reversedDepth; }

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
    static constexpr int kUnknown = 1 << 30;    // draws since the last whole clear: not known
    int m_drawsSinceClear = kUnknown;
    int m_slicesSinceClear = 0;     // the slice count of the draws since then
    bool m_restart = false;         // restartSlices(): the next draw clears
    double m_casterCoverage = 1.0;
    double m_slicedCoverageLimit = kSlicedCoverage;
    int m_clearCount = 0;
    DepthSlice m_slice;
    WrittenTexels m_written;
};

} // namespace shadowlab
