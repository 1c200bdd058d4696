#pragma once

#include "GlObject.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <memory>

namespace shadowlab {

// The min/max depth mip of a shadow map, for penumbra-only filtering (filter.early_out): an
// RG32F texture whose level k holds, per texel, the lowest and highest depth of the
// 2^(k+1) x 2^(k+1) map texels under it, down to 1 x 1. A wide filter reads at most four texels
// to learn that its whole footprint is lit or shadowed and skips its taps. Rebuilt only when the
// map changes (after a shadow pass), a pass per level.
class DepthRangePass {
public:
    explicit DepthRangePass(GlFunctions* gl);

    // Builds every level from `map`'s depth texture (reallocating when the map size changed).
    void build(const ShadowMap& map);

    GLuint texture() const { return m_texture.id(); }
    int levels() const { return m_levels; }

private:
    void allocate(int mapSize);

    GlFunctions* m_gl;
    std::unique_ptr<ShaderProgram> m_fromDepth;
    std::unique_ptr<ShaderProgram> m_fromRange;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlFramebuffer m_framebuffer;
    GlTexture m_texture;
    int m_mapSize = 0;
    int m_levels = 0;
};

} // namespace shadowlab
