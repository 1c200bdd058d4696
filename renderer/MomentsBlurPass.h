#pragma once

#include "MomentsMap.h"
#include "ShaderProgram.h"

#include <vector>

namespace shadowlab {

// Moments blur: a separable Gaussian over the moments map, horizontal into the map's scratch
// texture and vertical back, then the mip chain when the map has one.
class MomentsBlurPass {
public:
    explicit MomentsBlurPass(GlFunctions* gl);

    // `width` taps (0 or 1: no blur, only the mips). Returns the number of full-map draws.
    int render(const MomentsMap& map, int width);

    // The weights of a `width`-tap kernel, centre first then one side (pure; for tests): a
    // Gaussian of sigma width / 4, normalised so both sides and the centre sum to 1.
    static std::vector<float> weights(int width);

private:
    GlFunctions* m_gl;
    ShaderProgram m_program;
    GLint m_source, m_step, m_radius, m_weights;
    GlVertexArray m_emptyVertexArray;
    GlSampler m_sampler;
};

} // namespace shadowlab
