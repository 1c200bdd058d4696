#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

namespace shadowlab {

// Where in the depth buffer's [0, 1] a draw of the map wrote its conventional depth d (0 at the
// light's near plane, 1 at its far plane): stored = offset + d * scale. Above offset + scale
// lies a gap, then what earlier draws left (DepthSlices::beginDraw): from `emptyFrom` up a
// stored value reads as the far plane, as a cleared texel does.
struct DepthSlice {
    // Between slices: 16 steps of a 24-bit depth, so no value rounds into its neighbour's.
    static constexpr double kGap = 1.0 / (1 << 20);

    double offset = 0.0;
    double scale = 1.0;
    double emptyFrom = 1.0;

    double stored(double depth) const { return offset + depth * scale; }
    // A stored value as conventional depth, at most 1, as the shaders read it.
    float depth(float storedValue) const;
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

// Depth slices (map.slices = n), the software profile's way of clearing a map
// (RasteriserTuning::depthSlices): a clear writes every texel, which costs a software
// rasteriser as much as the casters do. A map of one 24-bit view is instead cleared once in n
// draws: draw k after a clear writes its depth into the k-th slice of [0, 1] from the top, 1/n
// wide less a gap at its top, nearer than every slice before it, so what the earlier draws left
// compares as beyond the far plane, lit, exactly as a cleared texel does. It costs log2(n) bits
// of the 24. A point light's six faces move to the next slice together, once per pass
// (ShadowMap::beginPass), so one slice still reads the whole map. Cascades, virtual pages,
// reversed (float) depth, whose precision lies near 0, and spot and warped maps (core's
// slicesDepth) clear every draw. The cycle of one map's draws and clears; the lit pass, the
// depth range and the depth view read the map through current().
class DepthSlices {
public:
    struct Draw {
        bool clear = true;          // clear the tile before drawing
        DepthSlice slice;           // where the draw writes
    };
    // Before a draw asking for `slices` (FramePlan::slices): into a slice where `sliceable` (the
    // whole map of one 24-bit view with conventional depth) and the casters' coverage allows,
    // else after a clear.
    Draw beginDraw(int slices, bool sliceable);
    // After a clear of the whole map (`whole`) or of a part of it.
    void cleared(bool whole);
    // Contents unknown (a new texture, another depth convention): the next draw clears.
    void reset();
    // The next draw clears and starts again at the first slice.
    void restart() { m_restart = true; }
    // Where the last draw wrote: how lookups read the map now.
    const DepthSlice& current() const { return m_slice; }
    // Which slice since the last clear that is (0: the first, or not sliced).
    int index() const { return m_slice.scale < 1.0 ? m_drawsSinceClear - 1 : 0; }

    // The share of the map the next draw's casters may cover (the area of their reach boxes,
    // ShadowReach, which bound their footprints). A draw into a slice reads each texel its
    // casters cover from memory, where after a clear it finds it in the cache, so a draw whose
    // boxes cover more than `limit` (map.slice_coverage) clears (docs/performance.md has the
    // figures).
    void setCasterCoverage(double share, double limit)
    {
        m_casterCoverage = share;
        m_coverageLimit = limit;
    }
    double casterCoverage() const { return m_casterCoverage; }

private:
    static constexpr int kUnknown = 1 << 30;    // draws since the last whole clear: not known
    int m_drawsSinceClear = kUnknown;
    int m_slicesSinceClear = 0;     // the slice count of the draws since then
    bool m_restart = false;         // restart(): the next draw clears
    double m_casterCoverage = 1.0;
    double m_coverageLimit = 1.0;
    DepthSlice m_slice;
};

} // namespace shadowlab
