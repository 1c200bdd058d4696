#include "SampleStats.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

double percentile(const std::vector<double>& sorted, double p)
{
    const double position = p * double(sorted.size() - 1);
    const auto lower = std::size_t(std::floor(position));
    const std::size_t upper = std::min(lower + 1, sorted.size() - 1);
    const double t = position - double(lower);
    return sorted[lower] * (1.0 - t) + sorted[upper] * t;
}

} // namespace

SampleStats summarize(std::vector<double> samples)
{
    SampleStats s;
    if (samples.empty())
        return s;
    std::sort(samples.begin(), samples.end());
    s.count = int(samples.size());
    s.median = percentile(samples, 0.5);
    s.p10 = percentile(samples, 0.1);
    s.p90 = percentile(samples, 0.9);
    s.min = samples.front();
    s.max = samples.back();
    double sum = 0.0;
    for (double v : samples)
        sum += v;
    s.mean = sum / double(samples.size());
    return s;
}

} // namespace shadowlab
