#include "ErrorNoise.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr double kUnresolvedPixels = 3.0;

} // namespace

double errorNoisePixels(double count)
{
    return std::max(kUnresolvedPixels, 2.0 * std::sqrt(std::max(0.0, count)));
}

bool clearlyFewer(double count, double other)
{
    return count + errorNoisePixels(count) < other - errorNoisePixels(other);
}

} // namespace shadowlab
