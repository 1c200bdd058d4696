#include "Flicker.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

FlickerResult measureFlicker(const std::vector<VisibilityBuffer>& frames)
{
    FlickerResult result;
    result.frames = int(frames.size());
    if (frames.empty())
        return result;
    const VisibilityBuffer& first = frames.front();
    for (int i = 0; i < first.pixelCount(); ++i)
        result.pixels += first.mask(i) == VisibilityBuffer::FacingLight;
    double flipSum = 0.0, changeSum = 0.0;
    int pairs = 0;
    for (std::size_t k = 1; k < frames.size(); ++k) {
        const VisibilityBuffer& a = frames[k - 1];
        const VisibilityBuffer& b = frames[k];
        if (a.size != b.size)
            continue;
        int counted = 0, flips = 0;
        double change = 0.0;
        for (int i = 0; i < a.pixelCount(); ++i) {
            if (a.mask(i) != VisibilityBuffer::FacingLight || b.mask(i) != VisibilityBuffer::FacingLight)
                continue;
            const float va = a.visibility(i), vb = b.visibility(i);
            ++counted;
            flips += (va >= 0.5f) != (vb >= 0.5f);
            change += std::abs(double(va) - double(vb));
        }
        if (counted == 0)
            continue;
        const double share = double(flips) / counted;
        flipSum += share;
        changeSum += change / counted;
        result.worstPair = std::max(result.worstPair, share);
        ++pairs;
    }
    if (pairs > 0) {
        result.flicker = flipSum / pairs;
        result.meanChange = changeSum / pairs;
    }
    return result;
}

} // namespace shadowlab
