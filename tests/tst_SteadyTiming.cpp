// When the report stops timing a configuration: a steady series after its minimum, a noisy one
// or one that a slow spell shifts only later, and never past the cap. Series are made by hand;
// nothing is timed.
#include "SteadyTiming.h"

#include <QtTest>

#include <cmath>

using namespace shadowlab;

namespace {

// `count` frames around `ms`, jittered by a fixed pattern of +-`jitter` ms.
std::vector<double> series(int count, double ms, double jitter)
{
    std::vector<double> s;
    for (int i = 0; i < count; ++i)
        s.push_back(ms + jitter * std::sin(1.7 * i));
    return s;
}

std::vector<double> joined(std::vector<double> a, const std::vector<double>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The frames `rule` times of `source` before it stops, batch by batch as the report does (the
// last batch cut short at the cap).
int framesTimed(const std::vector<double>& source, const SteadyTiming& rule)
{
    std::vector<double> timed;
    while (!timingIsSteady(timed, rule) && timed.size() < source.size()) {
        for (int i = 0; i < rule.batch && timed.size() < source.size() && int(timed.size()) < rule.maximum; ++i)
            timed.push_back(source[timed.size()]);
    }
    return int(timed.size());
}

} // namespace

class tst_SteadyTiming : public QObject {
    Q_OBJECT

private slots:
    void steadySeriesStopsAtTheMinimum_data()
    {
        QTest::addColumn<double>("ms");
        QTest::addColumn<double>("jitter");
        QTest::newRow("constant") << 8.0 << 0.0;
        QTest::newRow("1 % jitter") << 8.0 << 0.08;
        QTest::newRow("fast frame") << 0.4 << 0.01;
        QTest::newRow("slow frame") << 120.0 << 3.0;
    }
    void steadySeriesStopsAtTheMinimum()
    {
        QFETCH(double, ms);
        QFETCH(double, jitter);
        const SteadyTiming rule;
        QCOMPARE(framesTimed(series(200, ms, jitter), rule), rule.minimum);
    }

    // A slow spell of a shared machine in the second batch moves the median by most of the
    // band: timing goes on until the summary holds again, or to the cap.
    void slowSpellKeepsTiming()
    {
        const SteadyTiming rule;
        const std::vector<double> spell = joined(series(rule.batch, 8.0, 0.1), series(200, 16.0, 0.1));
        QVERIFY(framesTimed(spell, rule) > rule.minimum);
    }

    // Frames that scatter across their whole band move the percentiles for longer than a steady
    // series does.
    void noisySeriesKeepsTiming()
    {
        std::vector<double> noisy;
        std::uint32_t state = 12345u;
        for (int i = 0; i < 200; ++i) {
            state = state * 1664525u + 1013904223u;
            const double u = double(state >> 8) / 16777216.0;
            noisy.push_back(5.0 + 10.0 * u);   // 5-15 ms, every frame anywhere in it
        }
        const SteadyTiming rule;
        QVERIFY(framesTimed(noisy, rule) > rule.minimum);
    }

    void neverPastTheCap()
    {
        SteadyTiming rule;
        rule.maximum = 20;
        // A machine that slows down batch after batch: the median never holds.
        std::vector<double> drifting;
        for (int i = 0; i < 100; ++i)
            drifting.push_back(5.0 * (1 + i / rule.batch));
        QCOMPARE(framesTimed(drifting, rule), 20);
        QVERIFY(timingIsSteady(std::vector<double>(20, 1.0), rule));
    }

    // Below the minimum nothing is steady, and a minimum above the cap gives way to the cap,
    // so minimum == maximum times a fixed count.
    void minimumAndCap()
    {
        SteadyTiming rule;
        QVERIFY(!timingIsSteady({}, rule));
        QVERIFY(!timingIsSteady(std::vector<double>(rule.minimum - 1, 3.0), rule));
        QVERIFY(timingIsSteady(std::vector<double>(rule.minimum, 3.0), rule));
        rule.minimum = rule.maximum = 30;
        QCOMPARE(framesTimed(series(200, 8.0, 0.0), rule), 30);
    }
};

QTEST_APPLESS_MAIN(tst_SteadyTiming)
#include "tst_SteadyTiming.moc"
