#include "Flicker.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Flips between consecutive frames; with `references` (one per frame), only at points that
// stayed put and only those the reference does not share, and the change the reference does
// not explain.
FlickerResult flickerOver(const std::vector<VisibilityBuffer>& frames, const std::vector<std::vector<float>>* references)
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
            if (!references) {
                ++counted;
                flips += (va >= 0.5f) != (vb >= 0.5f);
                change += std::abs(double(va) - double(vb));
                continue;
            }
            // A receiver that moved (a moving object's surface) is not the same point.
            if (glm::vec3(a.positionVisibility[std::size_t(i)]) != glm::vec3(b.positionVisibility[std::size_t(i)]))
                continue;
            const float ra = (*references)[k - 1][std::size_t(i)], rb = (*references)[k][std::size_t(i)];
            ++counted;
            flips += ((va >= 0.5f) != (vb >= 0.5f)) && ((ra >= 0.5f) == (rb >= 0.5f));
            change += std::abs((double(vb) - double(va)) - (double(rb) - double(ra)));
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

} // namespace

FlickerResult measureFlicker(const std::vector<VisibilityBuffer>& frames)
{
    return flickerOver(frames, nullptr);
}

FlickerResult measureTimeFlicker(const std::vector<VisibilityBuffer>& frames, const std::vector<std::vector<float>>& references)
{
    return flickerOver(frames, &references);
}

} // namespace shadowlab
