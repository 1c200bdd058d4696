#pragma once

#include "GlObject.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <memory>
#include <optional>
#include <utility>

namespace shadowlab {

// The min/max depth mip of a shadow map, for penumbra-only filtering (filter.early_out): an
// RG32F texture whose level k holds, per texel, the lowest and highest depth of the
// 2^(k+1) x 2^(k+1) map texels under it, down to 1 x 1. A wide filter reads at most four texels
// to learn that its whole footprint is lit or shadowed and skips its taps. Rebuilt only when the
// map changes (after a shadow pass), a pass per level.
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

    GLuint texture() const { return m_texture.id(); }
    int levels() const { return m_levels; }

private:
    void allocate(int mapSize);

    GlFunctions* m_gl;
    Contents m_contents;
    std::unique_ptr<ShaderProgram> m_fromDepth;
    std::unique_ptr<ShaderProgram> m_fromRange;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlFramebuffer m_framebuffer;
    GlTexture m_texture;
    int m_mapSize = 0;
    int m_levels = 0;
};

} // namespace shadowlab
