#include "Ssim.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr int kWindowRadius = 5;        // 11 x 11
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;     // (K1 L)², L = 1
constexpr double kC2 = 0.03 * 0.03;     // (K2 L)²

// The 1-D Gaussian whose outer product is the window, normalised to sum 1.
std::vector<double> gaussianTaps(int radius)
{
    std::vector<double> taps;
    for (int i = -radius; i <= radius; ++i)
        taps.push_back(std::exp(-double(i * i) / (2.0 * kSigma * kSigma)));
    double sum = 0.0;
    for (double t : taps)
        sum += t;
    for (double& t : taps)
        t /= sum;
    return taps;
}

// `values` (width x height) weighted by the separable window at every position where the
// window lies wholly inside: (width - n + 1) x (height - n + 1) local means, n taps. Across
// the rows first, then down the columns of that: 2n taps a pixel instead of n².
std::vector<float> windowMeans(const std::vector<float>& values, int width, int height, const std::vector<double>& taps)
{
    const int n = int(taps.size());
    const int outWidth = width - n + 1, outHeight = height - n + 1;
    std::vector<float> across(std::size_t(outWidth) * std::size_t(height));
    for (int y = 0; y < height; ++y) {
        const float* row = values.data() + std::size_t(y) * std::size_t(width);
        for (int x = 0; x < outWidth; ++x) {
            double s = 0.0;
            for (int k = 0; k < n; ++k)
                s += taps[std::size_t(k)] * row[x + k];
            across[std::size_t(y) * std::size_t(outWidth) + std::size_t(x)] = float(s);
        }
    }
    std::vector<float> means(std::size_t(outWidth) * std::size_t(outHeight));
    for (int y = 0; y < outHeight; ++y) {
        for (int x = 0; x < outWidth; ++x) {
            double s = 0.0;
            for (int k = 0; k < n; ++k)
                s += taps[std::size_t(k)] * across[std::size_t(y + k) * std::size_t(outWidth) + std::size_t(x)];
            means[std::size_t(y) * std::size_t(outWidth) + std::size_t(x)] = float(s);
        }
    }
    return means;
}

std::vector<float> product(const std::vector<float>& a, const std::vector<float>& b)
{
    std::vector<float> p(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        p[i] = a[i] * b[i];
    return p;
}

} // namespace

double meanSsim(const GreyImage& a, const GreyImage& b)
{
    if (a.width != b.width || a.height != b.height || a.width <= 0 || a.height <= 0)
        return 0.0;
    const int radius = std::min({kWindowRadius, (a.width - 1) / 2, (a.height - 1) / 2});
    const std::vector<double> taps = gaussianTaps(radius);
    const auto means = [&](const std::vector<float>& v) { return windowMeans(v, a.width, a.height, taps); };
    const std::vector<float> meanA = means(a.values), meanB = means(b.values);
    const std::vector<float> meanAA = means(product(a.values, a.values)), meanBB = means(product(b.values, b.values));
    const std::vector<float> meanAB = means(product(a.values, b.values));
    double sum = 0.0;
    for (std::size_t i = 0; i < meanA.size(); ++i) {
        const double muA = meanA[i], muB = meanB[i];
        // E[x²] - mu² may round below 0 on a flat patch, by far less than C2.
        const double varA = meanAA[i] - muA * muA, varB = meanBB[i] - muB * muB;
        const double covariance = meanAB[i] - muA * muB;
        sum += (2.0 * muA * muB + kC1) * (2.0 * covariance + kC2) / ((muA * muA + muB * muB + kC1) * (varA + varB + kC2));
    }
    return sum / double(meanA.size());
}

} // namespace shadowlab
