#pragma once

#include "MomentsMap.h"
#include "ShaderProgram.h"

#include <QRect>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace shadowlab {

// Moments blur: a separable Gaussian over the moments map, horizontal into the map's scratch
// texture and vertical back, then the mip chain when the map has one.
class MomentsBlurPass {
public:
    explicit MomentsBlurPass(GlFunctions* gl);

    // `width` taps (0 or 1: no blur, only the mips). Returns the number of draws.
    // Within `tile` (texels; empty: the whole map): a view's taps never reach its neighbours.
    // Only within its radius of `drawn` (core/CasterTexels.h; nullopt: the whole tile): outside,
    // the map holds the far plane's moments, a constant the blur leaves as it is.
    int render(const MomentsMap& map, int width, const QRect& tile = QRect(), const std::optional<QRect>& drawn = std::nullopt);
    // Texels the last render() wrote over both axes, and where it wrote the map (its second
    // axis: the casters grown by the radius).
    qint64 lastTexels() const { return m_lastTexels; }
    QRect lastWritten() const { return m_lastWritten; }

    // The weights of a `width`-tap kernel, centre first then one side (pure; for tests): a
    // Gaussian of sigma width / 4, normalised so both sides and the centre sum to 1.
    static std::vector<float> weights(int width);

private:
    // One variant per radius (compiled on first use), so the tap loop unrolls.
    struct Program {
        Program(GlFunctions* gl, int radius);
        ShaderProgram program;
        GLint source, step, weights, tileMin, tileMax;
    };

    GlFunctions* m_gl;
    std::map<int, std::unique_ptr<Program>> m_programs;
    GlVertexArray m_emptyVertexArray;
    GlSampler m_sampler;
    qint64 m_lastTexels = 0;
    QRect m_lastWritten;
};

} // namespace shadowlab
