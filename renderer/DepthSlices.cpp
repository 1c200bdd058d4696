#include "DepthSlices.h"

#include "SharedShaderCode.h"

#include <utility>

namespace shadowlab {

float DepthSlice::depth(float storedValue) const
{
    return glsl::sliceDepthOf(storedValue, uniform());
}

DepthSlices::Draw DepthSlices::beginDraw(int slices, bool sliceable)
{
    if (!sliceable || slices <= 1 || m_coverageLimit <= 0.0 || m_casterCoverage > m_coverageLimit) {
        m_drawsSinceClear = kUnknown;
        m_slice = {};
        m_restart = false;
        return {};
    }
    Draw draw;
    // Slices of another count since the clear lie anywhere in [0, 1]: clear them first; so
    // does a draw after restart().
    const bool restart = std::exchange(m_restart, false);
    draw.clear = restart || m_drawsSinceClear >= slices || slices != m_slicesSinceClear;
    if (draw.clear) {
        m_drawsSinceClear = 0;
        m_slicesSinceClear = slices;
    }
    const int k = m_drawsSinceClear++;
    const double top = 1.0 - double(k) / slices;
    draw.slice = {top - 1.0 / slices, 1.0 / slices - DepthSlice::kGap, top - 0.5 * DepthSlice::kGap};
    m_slice = draw.slice;
    return draw;
}

void DepthSlices::cleared(bool whole)
{
    m_drawsSinceClear = whole ? 0 : kUnknown;
    m_slice = {};
    m_restart = false;
}

void DepthSlices::reset()
{
    m_drawsSinceClear = kUnknown;
    m_slice = {};
}

} // namespace shadowlab
