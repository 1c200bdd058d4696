#pragma once

#include "GpuScene.h"
#include "LightMath.h"
#include "MomentsMap.h"
#include "ProgramCache.h"
#include "Settings.h"
#include "ShaderProgram.h"

#include <QRect>

#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab {

// Moments pass: renders the casters from the light into a moments map, each fragment encoded by
// the selected moment technique's GLSL (its row's file with MOMENTS_PASS), over a map first
// filled with the far plane's moments (zeros for a technique that stores coverage). Depth
// clamping and caster culling as in the depth pass; every face is drawn and no polygon offset
// applied (bias.cull_front and the offsets are the depth map's cures for acne, which moments do
// not need). Cut-out casters leave their holes out (their ALPHA_CUTOUT variant) unless
// shadow.cutouts is off.
class MomentsPass {
public:
    explicit MomentsPass(GlFunctions* gl);

    // Where in a tile the pass draws (core/CasterTexels.h), in texels of the map.
    struct Area {
        std::optional<QRect> drawn;     // around the casters; nullopt: anywhere
        // Within `drawn`, apart: each caster's rectangle, grown where floors go around them
        // (drawsFloorsAroundCasters); empty: `drawn` whole.
        std::vector<QRect> pieces;
        bool floorsInPieces = false;    // floors are drawn in `pieces`, once in each
    };

    // The most pieces a pass clears or draws a floor into; more are joined into their bounds.
    static constexpr std::size_t kMostPieces = 8;

    // Returns the number of caster draw calls. `settings.filter.mode` must be a moment technique.
    // Into `tile` of the map (texels; empty: the whole map), for one view of several, within
    // `area`: what earlier draws wrote there and `area` get the far plane's moments first (in
    // pieces where it has them and the map is not cleared whole), and the casters are drawn
    // within `area.drawn` only. `casters`: only the still or the moving ones; `clear` false
    // draws over what the tile holds (the moving casters over a cache's copy,
    // renderer/ShadowCache.h).
    int render(const GpuScene& scene, const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& tile, const Area& area,
               CasterSet casters = CasterSet::All, bool clear = true);
    // Fills what draws wrote in `tile` with the far plane's moments: every lookup reads lit.
    void clear(const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& tile = QRect());

    // Whether a map of one view drawn only in part (coverage, or floors around the casters) is
    // cleared only where it was or will be written, not whole (RasteriserTuning::clearsWrittenMoments).
    void clearWrittenOnly(bool on) { m_clearsWritten = on; }

    // Texels cleared and filled with the far plane's moments since the last call.
    qint64 takeClearedTexels() { return std::exchange(m_clearedTexels, 0); }

    // Whether the pass leaves out floors the light is above (bias.skip_floors): only for a
    // technique that stores coverage. Without it a receiver must be in the map, as its own
    // depth, for its footprint to read lit (the far plane behind it reads as a gap of light
    // to the exponential warps, and halves a caster's penumbra over it).
    static bool leavesOutFloors(const Settings& settings);
    // Whether, without coverage (evsm4, msm), those floors are drawn only around the casters,
    // where a lookup near one reads them: the lookups' reach is finite (core/ShadowReach.h), so
    // a receiver beyond it is lit without a lookup, and a floor casts nothing. The pass is then
    // as large as the casters' footprint, not the map (MomentsStorage's drawnArea).
    static bool drawsFloorsAroundCasters(const Settings& settings);

    // The #defines of the variant for `settings` (exposed for tests).
    static QStringList variantDefines(const Settings& settings, bool perspective);

private:
    struct Program {
        Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint mvp, depthRange, farPlane, exponentPositive, exponentNegative, alphaCutoff;
    };

    // The variant for `settings`, compiled on first use; with `cutout` the one that discards
    // where a cut-out caster's mask is clear.
    Program& program(const LightFrame& light, const Settings& settings, bool cutout);
    // The light's uniforms every variant drawing this map reads.
    void setLightUniforms(Program& p, const LightFrame& light, const Settings& settings);
    // What names the far plane's moments of `settings` (MomentsMap::encodedBy, and the cache of
    // their values): the variant, the format and the exponents.
    static QString encoding(const LightFrame& light, const Settings& settings);
    // Clears the depth and writes the far plane's moments within `clear`.
    Program& begin(const LightFrame& light, const Settings& settings, MomentsMap& map, const QRect& clear);
    // Draws `item` once in each of `pieces` (cut to `area`), scissored to it; then restores the
    // pass's scissor (`area`, or none where not `scissored`). Returns the draws.
    int drawInPieces(const GpuScene& scene, const DrawItem& item, const std::vector<QRect>& pieces, const QRect& area, bool scissored);
    // begin() for each of `rects` (none: only the program set up); the program it set up.
    Program& clearFirst(const LightFrame& light, const Settings& settings, MomentsMap& map, const std::vector<QRect>& rects);

    GlFunctions* m_gl;
    GlVertexArray m_emptyVertexArray;   // for the far-plane triangle
    ProgramCache<Program> m_programs;
    qint64 m_clearedTexels = 0;
    bool m_clearsWritten = false;
    // The far plane's moments per variant and exponents, as its encoding drew them.
    std::map<QString, std::array<GLfloat, 4>> m_farMoments;
};

} // namespace shadowlab
