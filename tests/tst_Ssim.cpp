// SSIM as the paper defines it, and the orderings a reader of the report relies on: alike
// images score 1, a moved shadow edge scores worse than a stray pixel, and a change of
// brightness worse than nothing but far better than noise of the same mean squared error.
// No GL: images are made by hand.
#include "Ssim.h"

#include <QRandomGenerator>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace shadowlab;

namespace {

GreyImage image(int width, int height, const std::function<double(int, int)>& value)
{
    GreyImage g{width, height, std::vector<float>(std::size_t(width) * std::size_t(height))};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            g.values[std::size_t(y) * std::size_t(width) + std::size_t(x)] = float(value(x, y));
    return g;
}

double at(const GreyImage& g, int x, int y)
{
    return g.values[std::size_t(y) * std::size_t(g.width) + std::size_t(x)];
}

// The paper's formula written out the slow way, independent of the implementation: the full
// 11 x 11 Gaussian window at every position inside the image, the variances and covariance as
// weighted sums of squared deviations from the window's mean, then the mean over windows.
double slowSsim(const GreyImage& a, const GreyImage& b)
{
    double weights[11][11], total = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i)
            total += weights[j][i] = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2.0 * 1.5 * 1.5));
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0.0;
    int windows = 0;
    for (int y = 0; y + 11 <= a.height; ++y) {
        for (int x = 0; x + 11 <= a.width; ++x) {
            double muA = 0.0, muB = 0.0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) {
                    muA += weights[j][i] / total * at(a, x + i, y + j);
                    muB += weights[j][i] / total * at(b, x + i, y + j);
                }
            double varA = 0.0, varB = 0.0, cov = 0.0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) {
                    const double w = weights[j][i] / total, da = at(a, x + i, y + j) - muA, db = at(b, x + i, y + j) - muB;
                    varA += w * da * da;
                    varB += w * db * db;
                    cov += w * da * db;
                }
            sum += (2 * muA * muB + c1) * (2 * cov + c2) / ((muA * muA + muB * muB + c1) * (varA + varB + c2));
            ++windows;
        }
    }
    return sum / windows;
}

GreyImage noise(int width, int height, quint32 seed)
{
    QRandomGenerator random(seed);
    return image(width, height, [&](int, int) { return random.generateDouble(); });
}

// A lit floor (0.8) with a shadow (0.3) left of column `edge`.
GreyImage shadowEdge(int edge, int width = 48, int height = 32)
{
    return image(width, height, [=](int x, int) { return x < edge ? 0.3 : 0.8; });
}

} // namespace

class tst_Ssim : public QObject {
    Q_OBJECT

private slots:
    void identicalImagesScoreOne()
    {
        const GreyImage a = noise(40, 30, 1);
        QCOMPARE(meanSsim(a, a), 1.0);
        const GreyImage flat = image(40, 30, [](int, int) { return 0.0; });
        QCOMPARE(meanSsim(flat, flat), 1.0);     // C1 and C2 keep 0/0 away
    }

    // Two flat images have no variance: SSIM is the luminance term alone,
    // (2 * 0.5 * 0.25 + C1) / (0.5² + 0.25² + C1) = 0.2501 / 0.3126.
    void flatImagesScoreTheirLuminanceTerm()
    {
        const GreyImage a = image(20, 16, [](int, int) { return 0.5; });
        const GreyImage b = image(20, 16, [](int, int) { return 0.25; });
        QVERIFY(qAbs(meanSsim(a, b) - 0.2501 / 0.3126) < 1e-6);
        QVERIFY(qAbs(meanSsim(b, a) - meanSsim(a, b)) < 1e-12);
    }

    void matchesThePaperWrittenOut()
    {
        const GreyImage a = noise(27, 19, 7);
        GreyImage b = a;
        QRandomGenerator random(8);
        for (float& v : b.values)
            v = float(std::clamp(v + 0.2 * (random.generateDouble() - 0.5), 0.0, 1.0));
        const GreyImage edge = shadowEdge(12, 27, 19), moved = shadowEdge(15, 27, 19);
        const std::pair<const GreyImage*, const GreyImage*> pairs[] = {{&a, &b}, {&edge, &moved}, {&a, &edge}};
        for (const auto& [left, right] : pairs) {
            const double expected = slowSsim(*left, *right), actual = meanSsim(*left, *right);
            QVERIFY2(qAbs(actual - expected) < 1e-5, qPrintable(QString("%1 vs %2").arg(actual).arg(expected)));
        }
    }

    // What the report's column is for: a shadow edge two pixels off is a worse picture than one
    // pixel of acne, and both are worse than none.
    void aMovedEdgeScoresLowerThanAStrayPixel()
    {
        const GreyImage truth = shadowEdge(24);
        GreyImage stray = truth;
        stray.values[std::size_t(16 * 48 + 36)] = 0.3f;    // one dark pixel on the lit floor
        const double strayScore = meanSsim(truth, stray);
        const double movedScore = meanSsim(truth, shadowEdge(26));
        qInfo("one stray pixel: SSIM %.5f; edge moved 2 px: SSIM %.5f", strayScore, movedScore);
        QVERIFY(strayScore < 1.0);
        QVERIFY(movedScore < strayScore);
        QVERIFY(meanSsim(truth, shadowEdge(28)) < movedScore);   // further is worse
    }

    // The paper's own point (its Fig. 2): a brightness shift keeps the structure, noise of the
    // same mean squared error does not.
    void aBrightnessShiftScoresAboveNoiseOfTheSameError()
    {
        const GreyImage a = image(48, 32, [](int x, int y) { return 0.3 + 0.4 * (0.5 + 0.5 * std::sin(x * 0.4) * std::cos(y * 0.3)); });
        GreyImage brighter = a, noisy = a;
        QRandomGenerator random(3);
        for (std::size_t i = 0; i < a.values.size(); ++i) {
            brighter.values[i] += 0.05f;
            noisy.values[i] += random.bounded(2) ? 0.05f : -0.05f;
        }
        const double shift = meanSsim(a, brighter), scattered = meanSsim(a, noisy);
        qInfo("brightness +0.05: SSIM %.4f; noise of +-0.05: SSIM %.4f", shift, scattered);
        QVERIFY(shift > 0.99);
        QVERIFY(scattered < shift - 0.1);
    }

    // Smaller than the window: the largest window that fits, still 1 for alike images and
    // finite otherwise; mismatched or empty images are not alike at all.
    void degenerateSizes()
    {
        const GreyImage small = noise(6, 3, 5), other = noise(6, 3, 6);
        QCOMPARE(meanSsim(small, small), 1.0);
        const double s = meanSsim(small, other);
        QVERIFY(std::isfinite(s) && s < 1.0);
        const GreyImage pixel = image(1, 1, [](int, int) { return 0.5; });
        QCOMPARE(meanSsim(pixel, pixel), 1.0);
        QCOMPARE(meanSsim(small, noise(3, 6, 5)), 0.0);
        QCOMPARE(meanSsim(GreyImage{}, GreyImage{}), 0.0);
    }
};

QTEST_GUILESS_MAIN(tst_Ssim)
#include "tst_Ssim.moc"
