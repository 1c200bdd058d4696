#pragma once

#include <vector>

namespace shadowlab {

// Median and spread of repeated measurements; robust to the odd slow frame on a shared machine.
struct SampleStats {
    int count = 0;
    double median = 0.0;
    double p10 = 0.0;   // 10th percentile
    double p90 = 0.0;   // 90th percentile
    double min = 0.0;
    double max = 0.0;
    double mean = 0.0;  // what a run of such frames costs on average, where a few slow ones count
};

// Percentiles by linear interpolation between order statistics; all zero for no samples.
SampleStats summarize(std::vector<double> samples);

} // namespace shadowlab
