#include "SteadyTiming.h"

#include "SampleStats.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

bool timingIsSteady(const std::vector<double>& samples, const SteadyTiming& rule)
{
    const int count = int(samples.size());
    if (count >= rule.maximum)
        return true;
    const int batch = std::max(1, rule.batch);
    if (count < std::max(rule.minimum, batch + 1))
        return false;
    const SampleStats all = summarize(samples);
    const SampleStats before = summarize(std::vector<double>(samples.begin(), samples.end() - batch));
    const double allowed = std::max(rule.bandTolerance * (all.p90 - all.p10), rule.medianTolerance * std::abs(all.median));
    return std::abs(all.median - before.median) <= allowed && std::abs(all.p10 - before.p10) <= allowed
        && std::abs(all.p90 - before.p90) <= allowed;
}

} // namespace shadowlab
