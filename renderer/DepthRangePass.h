#pragma once

#include "GlObject.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <QPoint>

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

namespace shadowlab {

// The min/max depth mip of a shadow map, for penumbra-only filtering (filter.early_out): level k
// holds, per texel, the lowest and highest depth of the 2^(k+2) x 2^(k+2) map texels under it,
// down to 1 x 1 (no level of 2 x 2: the narrowest footprint a filter asks about spans 4 texels). A wide filter reads at most four texels to learn that its whole footprint is lit
// or shadowed and skips its taps. Rebuilt only when the map changes (after a shadow pass), a
// pass per level into a mip chain, then copied into one single-level RG32F atlas that the lit
// pass reads: a level chosen per pixel then never depends on the driver fetching a level per
// pixel (llvmpipe picks one level for each 2 x 2 quad of pixels).
//
// Atlas layout, with w0 the size of level 0 (the map's size over 4, rounded up) and level k of
// size w0 >> k: level 0 at (0, 0); level k >= 1 at (w0, w0 - 2 (w0 >> k)), a column to its right
// (shaders/shadow_filters.glsl, rangeTexel, reads the same rule).
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
    void build(const ShadowMap& map, bool reversedDepth = false);
    // The 1 x 1 level read back, as stored (raw depth): {min, max}, or nullopt when no texel
    // was written. Stalls until the build is done; for a view, once per shadow pass.
    std::optional<std::pair<float, float>> readTotal();

    // The atlas: RG32F, (w0 + w0 / 2) x w0, read with texelFetch at level 0.
    GLuint texture() const { return m_atlas.id(); }
    int levels() const { return m_levels; }

    static constexpr int kLevelZeroBlock = 4;   // map texels per side of a level-0 texel
    static int levelZeroSize(int mapSize) { return (mapSize + kLevelZeroBlock - 1) / kLevelZeroBlock; }
    // Where level `level` starts in the atlas, and its size (square).
    static QPoint levelOrigin(int levelZeroSize, int level);
    static int levelSize(int levelZeroSize, int level) { return std::max(levelZeroSize >> level, 1); }

private:
    void allocate(int mapSize);

    GlFunctions* m_gl;
    Contents m_contents;
    std::unique_ptr<ShaderProgram> m_fromDepth;
    std::unique_ptr<ShaderProgram> m_fromRange;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlFramebuffer m_framebuffer;
    GlFramebuffer m_atlasFramebuffer;
    GlTexture m_chain;  // the mip chain the passes build, level by level
    GlTexture m_atlas;
    int m_mapSize = 0;
    int m_levels = 0;
};

} // namespace shadowlab
