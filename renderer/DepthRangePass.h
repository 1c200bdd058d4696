#pragma once

#include "GlObject.h"
#include "ShaderConstants.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <QPoint>
#include <QSize>

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

// The min/max depth mip of a shadow map, for penumbra-only filtering (filter.early_out) and
// pcss's and dpcf's blocker search (the nearest depth under a search region): level k
// holds, per texel, the lowest and highest depth of the 2^(k+2) x 2^(k+2) map texels under it,
// down to 1 x 1 (no level of 2 x 2: the narrowest footprint a filter asks about spans 4 texels). A wide filter reads at most four texels to learn that its whole footprint is lit
// or shadowed and skips its taps. Rebuilt only when the map changes (after a shadow pass), a
// pass per level into a mip chain, then copied into one single-level RG32F atlas that the lit
// pass reads: a level chosen per pixel then never depends on the driver fetching a level per
// pixel (llvmpipe picks one level for each 2 x 2 quad of pixels).
//
// The map is every tile at once (a light's views side by side): a range texel near a tile's
// edge may take in a neighbour's texels too, which only widens its range, so a verdict drawn
// from it still holds for the taps, which stay inside their tile.
//
// Atlas layout, with w0 the size of level 0 (the map's width and height over 4, rounded up) and
// level k of size max(w0 >> k, 1) on each axis: level 0 at (0, 0); levels 1 and up stacked in a
// column to its right, level 1 at its bottom (levelOrigin(); the lit pass reads the same table,
// shaders/shadow_filters.glsl, rangeTexel).
//
// With Contents::Written texels nothing was drawn into (the far plane, or 0 in a reversed map)
// take no part, and readTotal() gives the nearest and farthest depth the map really holds: what
// the depth-map view stretches its colour ramp over.
class DepthRangePass {
public:
    enum class Contents { All, Written };
    explicit DepthRangePass(GlFunctions* gl, Contents contents = Contents::All);

    // Builds every level from `map`'s depth texture (reallocating when the map size changed).
    // `reversedDepth`: the map stores 1 - depth (empty texels hold 0); only Written reads it.
    // `written`, where the caller knows it (RasteriserTuning::rangesWrittenTexels): the texels
    // that may hold anything but the cleared value (the far plane in any slice). Level 0 is then
    // drawn only over those and over what the last build saw written; elsewhere the map held
    // the cleared value both times. Without it, the whole map.
    void build(const ShadowMap& map, bool reversedDepth = false, const std::vector<QRect>* written = nullptr);
    // The 1 x 1 level read back, as stored (raw depth): {min, max}, or nullopt when no texel
    // was written. Stalls until the build is done; for a view, once per shadow pass.
    std::optional<std::pair<float, float>> readTotal();

    // The atlas: RG32F, read with texelFetch at level 0.
    GLuint texture() const { return m_atlas.id(); }
    int levels() const { return int(m_origins.size()); }
    // Where level `level` lies in the atlas, and its size.
    QPoint levelOrigin(int level) const { return m_origins[std::size_t(level)]; }
    QSize levelSize(int level) const { return m_sizes[std::size_t(level)]; }

    static constexpr int kLevelZeroBlock = 4;   // map texels per side of a level-0 texel
    // Level-0 texels the last build drew: all of them, or those over the written texels.
    qint64 levelZeroTexelsDrawn() const { return m_levelZeroDrawn; }

private:
    void allocate(QSize mapSize);
    // Where level 0 is drawn this build (build's `written`), and what is kept for the next.
    std::vector<QRect> levelZeroAreas(const ShadowMap& map, const std::vector<QRect>* written);
    // Levels 1 and up, drawn into the chain, copied to their places in the atlas.
    void copyIntoAtlas();

    // Past it level 0's areas are drawn as their bounds.
    static constexpr std::size_t kMostAreas = 16;

    // depthrange.frag, from the map (level 0) or from the level below, and its uniforms.
    struct Program {
        Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint source, sourceSize, shadowSlice, empty;
    };

    GlFunctions* m_gl;
    Contents m_contents;
    std::unique_ptr<Program> m_fromDepth;
    std::unique_ptr<Program> m_fromRange;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlFramebuffer m_framebuffer;
    GlFramebuffer m_atlasFramebuffer;
    GlTexture m_chain;  // the mip chain the passes build, level by level
    GlTexture m_atlas;
    QSize m_mapSize;
    GLuint m_source = 0;                // the map's texture the last build read, and its cleared value
    bool m_sourceReversed = false;
    // Level-0 texels over what the last build's map had written; nullopt: the whole level.
    std::optional<std::vector<QRect>> m_lastWritten;
    qint64 m_levelZeroDrawn = 0;
    std::vector<QPoint> m_origins;
    std::vector<QSize> m_sizes;
};

} // namespace shadowlab
