// The report as its reader meets it: which configurations make the front (that noise in time
// or error does not change that, and that a ladder of small steps does not chain it away), lights kept apart, identical configurations measured once, an error
// axis that keeps small errors readable beside a large one, labels that do not cover each
// other, and error images zoomed where the errors are. No GL: rows are made by hand.
#include "ErrorNoise.h"
#include "ReportSweep.h"
#include "ReportWriter.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QImage>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <map>

using namespace shadowlab;

namespace {

// Seed at 640x360 measures about this many light-facing pixels.
constexpr int kPixels = 176553;

ReportRow row(const QString& label, double errorPercent, double medianMs, double spreadMs, const QString& light = QStringLiteral("ortho light"))
{
    ReportRow r;
    r.label = label;
    r.light = light;
    r.frame.count = 30;
    r.frame.median = medianMs;
    r.frame.p10 = medianMs - spreadMs;
    r.frame.p90 = medianMs + spreadMs;
    r.accuracy.hard.pixels = kPixels;
    r.accuracy.hard.misclassified = errorPercent / 100.0;
    r.accuracy.area.pixels = kPixels;
    r.accuracy.area.mae = errorPercent / 200.0;
    QImage errors(64, 36, QImage::Format_RGB32);
    errors.fill(qRgb(90, 90, 90));
    r.accuracy.hardErrors = errors;
    return r;
}

// A row whose misclassified pixels number `pixels`.
ReportRow counted(const QString& label, double pixels, double medianMs, double spreadMs)
{
    return row(label, 100.0 * pixels / kPixels, medianMs, spreadMs);
}

// What a report of seed at 640x360 states about its run.
ReportFacts seedFacts()
{
    ReportFacts facts;
    facts.scene = "seed";
    facts.size = QSize(640, 360);
    facts.areaSamplesPerPixel = 256;
    return facts;
}

QStringList front(const std::vector<ReportRow>& rows)
{
    QStringList names;
    for (const ReportRow& r : rows) {
        if (r.paretoFront)
            names << r.label;
    }
    names.sort();
    return names;
}

} // namespace

class tst_Report : public QObject {
    Q_OBJECT

private slots:
    // A moiré of partial shadow barely moves misclassified pixels or the area MAE: a row whose
    // picture is unlike both references is left off the fronts with its reason, and the rows it
    // would have beaten stay on; soft edges that match the area light's picture are not wrong.
    void visiblyWrongRowsAreNeverOnTheFront()
    {
        std::vector<ReportRow> rows{row("moire", 0.5, 4.0, 0.3), row("clean", 1.0, 8.0, 0.3), row("soft", 1.5, 12.0, 0.3)};
        rows[0].accuracy.ssim = 0.9;            // DSSIM 0.1 against the hard light's picture...
        rows[0].accuracy.areaSsim = 0.92;       // ...and 0.08 against the area light's
        rows[1].accuracy.ssim = 0.999;
        rows[1].accuracy.areaSsim = 0.99;
        rows[2].accuracy.ssim = 0.97;           // unlike the hard picture, like the area light's
        rows[2].accuracy.areaSsim = 0.998;
        markParetoFronts(rows);
        QVERIFY(!rows[0].paretoFront && !rows[0].areaFront);
        QVERIFY(visiblyWrong(rows[0]).contains("0.1000") && visiblyWrong(rows[0]).contains("0.0800"));
        QVERIFY(rows[1].paretoFront && rows[1].areaFront);      // beaten only by the wrong row
        QVERIFY(visiblyWrong(rows[2]).isEmpty());
        // Without an area reference the hard light's picture decides.
        rows[2].accuracy.areaSsim.reset();
        QVERIFY(!visiblyWrong(rows[2]).isEmpty());
    }

    // The report answers "which one": the cheapest row with nothing visibly wrong (never the
    // faster moiré), the most accurate within twice its time, the closest to the area light;
    // rows inside the noise of a pick are named as its ties, and the faster of tied rows wins.
    void recommendsWhatToPickAndWhy()
    {
        std::vector<ReportRow> rows{row("moire", 0.30, 3.0, 0.2), row("hard", 0.50, 4.0, 0.3), row("hw", 0.49, 4.1, 0.3),
                                    row("pcf", 0.20, 6.0, 0.3), row("poisson", 0.201, 7.5, 0.3), row("pcss", 0.10, 20.0, 1.0)};
        for (ReportRow& r : rows) {
            r.accuracy.ssim = 0.999;
            r.accuracy.areaSsim = 0.995;
        }
        rows[0].accuracy.ssim = 0.9;        // a moiré: unlike both pictures
        rows[0].accuracy.areaSsim = 0.9;
        rows[5].accuracy.area.mae = 0.0002; // the soft filter is the area light's match
        markParetoFronts(rows);
        const std::vector<Recommendation> picks = recommend(rows, rows[0].light);
        QCOMPARE(picks.size(), std::size_t(3));
        // hw ties hard in time and in error (0.49 % against 0.50 %, inside the noise): the faster is picked.
        QCOMPARE(picks[0].kind, Recommendation::Kind::Cheapest);
        QCOMPARE(picks[0].row->label, QStringLiteral("hard"));
        QCOMPARE(picks[0].ties.size(), std::size_t(1));
        QCOMPARE(picks[0].ties.front()->label, QStringLiteral("hw"));
        QVERIFY2(picks[0].reason().contains("hw (") && picks[0].reason().contains("as fast and as accurate"), qPrintable(picks[0].reason()));
        // Within 8 ms (2 x 4 ms): pcf and poisson tie in error, pcf is faster; pcss is over the budget.
        QCOMPARE(picks[1].kind, Recommendation::Kind::MostAccurate);
        QCOMPARE(picks[1].row->label, QStringLiteral("pcf"));
        QCOMPARE(picks[1].budget, 8.0);
        QCOMPARE(picks[1].ties.size(), std::size_t(1));
        QCOMPARE(picks[1].ties.front()->label, QStringLiteral("poisson"));
        QVERIFY2(picks[1].title().contains("8.00 ms"), qPrintable(picks[1].title()));
        QCOMPARE(picks[2].kind, Recommendation::Kind::ClosestToArea);
        QCOMPARE(picks[2].row->label, QStringLiteral("pcss"));
        QCOMPARE(visiblyWrongRows(rows, rows[0].light).size(), std::size_t(1));

        // Ties in time are not transitive: a row tied with the fastest can be clearly slower than
        // a third, and is then not the cheapest however accurate (the spider's map sizes).
        {
            std::vector<ReportRow> maps{row("map 256", 0.25, 2.37, 0.1), row("map 512", 0.17, 2.61, 0.1), row("map 1024", 0.062, 3.40, 0.1)};
            maps[0].frame.p90 = 3.3;
            maps[1].frame.p10 = 2.54;
            maps[1].frame.p90 = 2.81;
            maps[2].frame.p10 = 3.26;
            maps[2].frame.p90 = 3.68;
            for (ReportRow& r : maps)
                r.accuracy.ssim = 0.999;
            QCOMPARE(recommend(maps, maps[0].light).front().row->label, QStringLiteral("map 512"));
        }

        // The report leads with the answer, the JSON carries it, the moiré is named as never picked.
        QTemporaryDir dir;
        writeReport(dir.path(), rows, seedFacts());
        QFile page(dir.filePath("report.html"));
        QVERIFY(page.open(QIODevice::ReadOnly));
        const QString html = QString::fromUtf8(page.readAll());
        QVERIFY(html.indexOf("What to pick") < html.indexOf("<svg"));
        QVERIFY(html.contains("Never picked") && html.contains(">moire</span>"));
        QFile json(dir.filePath("report.json"));
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonArray recommended = QJsonDocument::fromJson(json.readAll()).object().value("recommendations").toArray();
        QCOMPARE(recommended.size(), 3);
        QCOMPARE(recommended[0].toObject().value("label").toString(), QStringLiteral("hard"));
        QCOMPARE(recommended[0].toObject().value("ties").toArray().first().toString(), QStringLiteral("hw"));

        // Every row visibly wrong: the least wrong picture is the one answer, said as such.
        for (ReportRow& r : rows)
            r.accuracy.areaSsim = r.accuracy.ssim = 0.9;
        rows[4].accuracy.areaSsim = 0.95;
        const std::vector<Recommendation> least = recommend(rows, rows[0].light);
        QCOMPARE(least.size(), std::size_t(1));
        QCOMPARE(least.front().kind, Recommendation::Kind::LeastWrong);
        QCOMPARE(least.front().row->label, QStringLiteral("poisson"));
        QVERIFY2(least.front().reason().contains("0.0500 against the area light's"), qPrintable(least.front().reason()));
        // One row left clean: it is the one pick, said as such.
        rows[3].accuracy.ssim = 0.999;
        const std::vector<Recommendation> only = recommend(rows, rows[0].light);
        QCOMPARE(only.size(), std::size_t(1));
        QCOMPARE(only.front().kind, Recommendation::Kind::Only);
        QCOMPARE(only.front().row->label, QStringLiteral("pcf"));
    }

    void frontHoldsUnderTimingNoise()
    {
        // fast/rough and slow/exact are the classic trade-off; "twin" is as fast as "exact"
        // within the noise, so it stays beside it though less accurate; "worse" is beaten by
        // "middle" on both axes beyond the noise.
        std::vector<ReportRow> rows{row("fast", 8.0, 4.0, 0.3), row("exact", 0.5, 10.0, 1.0), row("twin", 0.6, 9.7, 1.0),
                                    row("middle", 2.0, 6.0, 0.4), row("worse", 3.0, 8.0, 0.4)};
        markParetoFronts(rows);
        const QStringList expected{"exact", "fast", "middle", "twin"};
        QCOMPARE(front(rows), expected);
        // The medians wander within their spreads from run to run: the front stays.
        QRandomGenerator random(7);
        for (int run = 0; run < 200; ++run) {
            std::vector<ReportRow> noisy = rows;
            for (ReportRow& r : noisy) {
                const double spread = r.frame.p90 - r.frame.p10;
                r.frame.median = r.frame.p10 + random.generateDouble() * spread;
            }
            markParetoFronts(noisy);
            QCOMPARE(front(noisy), expected);
        }
    }

    // Seed at 640x360: map 256 → 512 → 1024 → … → pcf-dither4, each a little more accurate and a
    // little slower, every step within the noise of both axes. "Beaten when more accurate and
    // not clearly slower" chained the whole ladder away to its slow end. Ties stay together;
    // only a row clearly beaten on both axes leaves.
    void frontDoesNotChainAlongALadder()
    {
        std::vector<ReportRow> rows;
        for (int step = 0; step < 8; ++step)
            rows.push_back(counted(QStringLiteral("ladder %1").arg(step), 60.0 - 4.0 * step, 6.0 + 0.3 * step, 0.5));
        rows.push_back(counted("fast", 200.0, 3.0, 0.3));          // clearly faster than all, clearly worse
        rows.push_back(counted("beaten", 120.0, 9.0, 0.3));        // ladder 0 is faster and more accurate, clearly
        rows.push_back(counted("slow twin", 34.0, 12.0, 0.3));     // as accurate as the ladder's end, clearly slower
        markParetoFronts(rows);
        QStringList expected{"fast", "slow twin"};
        for (int step = 0; step < 8; ++step)
            expected << QStringLiteral("ladder %1").arg(step);
        expected.sort();
        QCOMPARE(front(rows), expected);

        // The user's rows: 256 clearly faster than dither4; dither4's 3 px against the defaults' 9
        // is a tie, not a win.
        std::vector<ReportRow> seed{counted("map 256", 33.0, 5.54, 0.9), counted("defaults", 9.0, 8.6, 0.6), counted("pcf-dither4", 3.0, 9.46, 0.49)};
        seed[0].frame.p90 = 6.41;
        seed[2].frame.p10 = 8.97;
        markParetoFronts(seed);
        QCOMPARE(front(seed), (QStringList{"defaults", "map 256", "pcf-dither4"}));
    }

    // A few pixels are no difference: the error's band is max(3, 2√n) pixels either side.
    void errorNoiseComesFromThePixelCount()
    {
        QCOMPARE(errorNoisePixels(0.0), 3.0);
        QCOMPARE(errorNoisePixels(100.0), 20.0);
        QVERIFY(!clearlyFewer(3.0, 9.0));       // 3 ± 3 against 9 ± 6
        QVERIFY(clearlyFewer(0.0, 12.0));
        QVERIFY(!clearlyFewer(400.0, 480.0));   // 400 ± 40 against 480 ± 44
        QVERIFY(clearlyFewer(400.0, 500.0));
        QVERIFY(!clearlyFewer(9.0, 3.0));
    }

    // On a count's axis (report --cost taps) the front weighs what any GPU is asked for, not
    // this machine's times: a configuration fast here but of many taps leaves it, one slow here
    // but of few taps joins it; counts within about 2 % tie; rows of two machines compare.
    void frontOnACountAxis()
    {
        std::vector<ReportRow> rows{counted("few taps, slow here", 400, 20.0, 0.5), counted("many taps, fast here", 400, 5.0, 0.5),
                                    counted("more accurate, dearer", 100, 30.0, 0.5), counted("as many taps, less accurate", 900, 40.0, 0.5)};
        const std::int64_t taps[] = {1'000'000, 9'000'000, 4'000'000, 1'010'000};
        for (std::size_t i = 0; i < rows.size(); ++i) {
            rows[i].counts.tapsPerLookup = 1;
            rows[i].counts.lookupFragments = taps[i];
        }
        markParetoFronts(rows);
        QCOMPARE(front(rows), (QStringList{"few taps, slow here", "many taps, fast here", "more accurate, dearer"}));
        for (ReportRow& r : rows)
            r.costAxis = CostAxis::Taps;
        rows[1].machine = QStringLiteral("another machine, 16 cores");   // counts compare across machines
        markParetoFronts(rows);
        // "many taps" is beaten by "more accurate, dearer", which has fewer taps and fewer
        // errors, though it was measured on another machine; "as many taps" ties in taps with
        // "few taps" (1 % apart), so it is not beaten, although it is less accurate.
        QCOMPARE(front(rows), (QStringList{"as many taps, less accurate", "few taps, slow here", "more accurate, dearer"}));
        QCOMPARE(lightsOf(rows).size(), 1);     // one group: counts do not stay with their machine
        QCOMPARE(costText(rows[0], costOf(rows[0]).median), QStringLiteral("1.00 M taps"));
        QCOMPARE(costAxisFromKey("samples"), std::optional(CostAxis::ShadowSamples));
        QVERIFY(!costAxisFromKey("ms"));
        // The picks say taps, not milliseconds.
        const std::vector<Recommendation> picks = recommend(rows, lightsOf(rows).front());
        QVERIFY(!picks.empty());
        QVERIFY2(picks.front().reason().contains(QStringLiteral("taps a frame")), qPrintable(picks.front().reason()));
        QVERIFY2(!picks.front().reason().contains(QStringLiteral(" ms")), qPrintable(picks.front().reason()));
        // A row whose count was not taken is nowhere on that axis: off the front, never picked.
        rows[0].counts.lookupFragments = -1;
        markParetoFronts(rows);
        QVERIFY(!rows[0].paretoFront);
        for (const Recommendation& pick : recommend(rows, lightsOf(rows).front()))
            QVERIFY(pick.row != &rows[0]);
    }

    // The area light has its own front, on MAE: a soft filter far closer to the penumbra is on
    // it though misclassifying as many pixels as the rest.
    void areaLightHasItsOwnFront()
    {
        std::vector<ReportRow> rows{counted("hard", 40.0, 5.0, 0.3), counted("pcf", 30.0, 7.0, 0.3), counted("pcss", 32.0, 12.0, 0.3)};
        rows[0].accuracy.area.mae = 0.006;
        rows[1].accuracy.area.mae = 0.009;
        rows[2].accuracy.area.mae = 0.002;
        markParetoFronts(rows);
        QCOMPARE(front(rows), (QStringList{"hard", "pcf", "pcss"}));   // 40, 30 and 32 px: a tie
        QCOMPARE(rows[2].areaFront, true);
        QCOMPARE(rows[1].areaFront, false);    // hard is clearly faster and clearly closer to the penumbra
        QCOMPARE(rows[0].areaFront, true);
        rows[0].accuracy.area.pixels = rows[1].accuracy.area.pixels = rows[2].accuracy.area.pixels = 0;
        markParetoFronts(rows);                // not traced: no area front at all
        QVERIFY(std::none_of(rows.begin(), rows.end(), [](const ReportRow& r) { return r.areaFront; }));
    }

    void eachLightHasItsOwnFront()
    {
        // Grazing light: every configuration is worse and slower than under the overhead one,
        // yet the best of them is on its light's front.
        std::vector<ReportRow> rows{row("overhead fast", 1.0, 4.0, 0.2, "overhead"), row("overhead slow", 0.2, 9.0, 0.2, "overhead"),
                                    row("grazing a", 12.0, 11.0, 0.2, "grazing"), row("grazing b", 20.0, 12.0, 0.2, "grazing")};
        markParetoFronts(rows);
        QCOMPARE(front(rows), (QStringList{"grazing a", "overhead fast", "overhead slow"}));
        Settings a, b;
        b.light.position = {3.0, 2.0, 4.0};
        QVERIFY(lightDescription(a) != lightDescription(b));
        QVERIFY(lightDescription(a).contains("(-2, 4, -1)"));
    }

    void identicalConfigurationsAreMeasuredOnce()
    {
        const Settings base = presetSettings(QStringLiteral("seed"));
        const std::vector<SweepEntry> sweep{{"defaults", {}},
                                            {"bias as default", {QStringLiteral("bias.slope=%1").arg(base.bias.slope), QStringLiteral("bias.min=%1").arg(base.bias.min)}},
                                            {"hard", {"filter.mode=hard"}},
                                            {"hard again", {"filter.mode=hard", QStringLiteral("map.size=%1").arg(base.map.size)}}};
        const std::vector<SweepConfiguration> distinct = distinctConfigurations(base, sweep);
        QCOMPARE(distinct.size(), std::size_t(2));
        QCOMPARE(distinct[0].label, QStringLiteral("defaults = bias as default"));
        QCOMPARE(distinct[1].label, QStringLiteral("hard = hard again"));
        QVERIFY(distinct[0].settings == base);

        // Every built-in sweep comes out with no two configurations alike and no label lost.
        for (const QString& name : builtInSweeps()) {
            const std::vector<SweepEntry> entries = loadSweep(name, base);
            const std::vector<SweepConfiguration> configurations = distinctConfigurations(base, entries);
            for (std::size_t i = 0; i < configurations.size(); ++i)
                for (std::size_t j = i + 1; j < configurations.size(); ++j)
                    QVERIFY2(!(configurations[i].settings == configurations[j].settings), qPrintable(name));
            for (const SweepEntry& e : entries) {
                QVERIFY2(std::any_of(configurations.begin(), configurations.end(),
                                     [&](const SweepConfiguration& c) { return c.label.split(" = ").contains(e.label); }),
                         qPrintable(e.label));
            }
        }
    }

    // The dock's sweep is the report's "around": on any base, each entry valid and distinct, the
    // base first, every technique tried, one change at a time.
    void sweepAroundVariesOneThingAtATime_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("seed") << "seed" << QStringList{};
        QTest::newRow("city, pcf 5, texel bias") << "city" << QStringList{"filter.mode=pcf", "filter.kernel=5", "bias.space=texel", "bias.slope=2", "bias.min=0.5"};
        QTest::newRow("largest map, culled") << "torus" << QStringList{"map.size=16384", "bias.cull_front=true"};
        QTest::newRow("smallest map, no bias") << "cubes" << QStringList{"map.size=16", "bias.slope=0", "bias.min=0"};
        QTest::newRow("4 cascades, vsm") << "seed" << QStringList{"shadow.cascades=4", "filter.mode=vsm"};
        QTest::newRow("point light") << "seed" << QStringList{"light.type=point"};
        QTest::newRow("foliage") << "foliage" << QStringList{};
    }

    void sweepAroundVariesOneThingAtATime()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        Settings base = presetSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(base, a);
        const std::vector<SweepEntry> entries = loadSweep(QStringLiteral("around"), base);
        QVERIFY(entries.size() > shadowTechniques().size());
        QVERIFY(entries.front().assignments.isEmpty());
        const std::vector<SweepConfiguration> configurations = distinctConfigurations(base, entries);   // throws on an invalid one
        QCOMPARE(configurations.size(), entries.size());
        QVERIFY(configurations.front().settings == base);
        for (const ShadowTechnique& t : shadowTechniques()) {
            QVERIFY2(std::any_of(configurations.begin(), configurations.end(), [&](const SweepConfiguration& c) { return c.settings.filter.mode == t.mode; }),
                     qPrintable(t.key));
        }
        for (const SweepConfiguration& c : configurations) {
            QVERIFY2(c.settings.map.size >= 16 && c.settings.map.size <= 16384, qPrintable(c.label));   // map.size's range
            QVERIFY2(c.label != QStringLiteral("map %1²").arg(base.map.size), qPrintable(c.label));
        }
        // The bias steps scale the bias as set, in its own units.
        const auto halved = std::find_if(configurations.begin(), configurations.end(), [](const SweepConfiguration& c) { return c.label == u"bias ×0.5"; });
        if (base.bias.slope > 0.0 || base.bias.min > 0.0) {
            QVERIFY(halved != configurations.end());
            QCOMPARE(halved->settings.bias.slope, base.bias.slope * 0.5);
            QCOMPARE(halved->settings.bias.min, base.bias.min * 0.5);
            QVERIFY(halved->settings.bias.space == base.bias.space);
        }
        // Masks are toggled only where the scene has cut-outs.
        const bool togglesMasks = std::any_of(configurations.begin(), configurations.end(),
                                              [&](const SweepConfiguration& c) { return c.settings.shadow.cutouts != base.shadow.cutouts; });
        QCOMPARE(togglesMasks, scene == u"foliage");
        // ... and sdsm only where there are cascades to split.
        const bool togglesSdsm = std::any_of(configurations.begin(), configurations.end(),
                                             [&](const SweepConfiguration& c) { return c.settings.shadow.depthFit != base.shadow.depthFit; });
        QCOMPARE(togglesSdsm, base.shadow.cascades > 1 && base.light.type == LightType::Directional);
    }

    // What is the same for every row is said once; what is on a front is named on its chart;
    // the error's noise is shown beside it.
    void pageFoldsZerosAndShowsTheNoise()
    {
        std::vector<ReportRow> rows{counted("hard", 40.0, 5.0, 0.3), counted("pcf", 30.0, 7.0, 0.3), counted("pcss", 32.0, 12.0, 0.3)};
        rows[0].accuracy.area.mae = 0.006;
        rows[1].accuracy.area.mae = 0.009;
        rows[2].accuracy.area.mae = 0.002;
        for (ReportRow& r : rows) {
            r.accuracy.hard.falseShadow = r.accuracy.hard.misclassified;   // no false light anywhere
            r.flicker.frames = 8;                                          // measured, and none flickers
            r.flicker.mapMoves = 7;
        }
        rows[2].flicker.mapMoves = 0;                                      // ... one because its maps never moved
        markParetoFronts(rows);
        QTemporaryDir dir;
        const ReportFacts facts = seedFacts();
        writeReport(dir.path(), rows, facts);
        QFile file(dir.filePath("report.html"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(file.readAll());

        QVERIFY(page.contains("No configuration flickers above 0.0005 %"));
        QVERIFY2(page.contains("In 1 of 3 configurations the light's maps did not move at all"), "a zero that measured nothing says so");
        QVERIFY(!page.contains("<th>flips %</th>"));
        QVERIFY(!page.contains("<th>false light %</th>") && page.contains("<th>false shadow %</th>"));
        QVERIFY(page.contains("Every configuration has false light"));
        QVERIFY(page.contains("<td>40 ± 13</td>"));                    // 40 px ± 2√40
        QVERIFY(page.contains("±3 px is 0.0017 % of 176,553 measured pixels"));
        // The area chart names pcss, the one far closer to the penumbra.
        const qsizetype second = page.indexOf("<svg", page.indexOf("</svg>"));
        const QString areaChart = page.mid(second, page.indexOf("</svg>", second) - second);
        QVERIFY(areaChart.contains("class=\"label\">pcss<"));
        QVERIFY(areaChart.contains("spread noise"));
    }

    // A walk not taken (--flicker-frames 0 or 1) is not "no flicker": every writer says it was
    // not measured, where a measured row gives its figure.
    void unmeasuredFlickerIsNotZero()
    {
        std::vector<ReportRow> rows{counted("hard", 40.0, 5.0, 0.3), counted("pcf", 30.0, 7.0, 0.3)};
        markParetoFronts(rows);
        QTemporaryDir dir;
        const ReportFacts facts = seedFacts();
        writeReport(dir.path(), rows, facts);
        QFile csv(dir.filePath("report.csv")), json(dir.filePath("report.json")), html(dir.filePath("report.html"));
        QVERIFY(csv.open(QIODevice::ReadOnly) && json.open(QIODevice::ReadOnly) && html.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
        const QStringList header = lines.at(0).split(',');
        const qsizetype flips = header.indexOf("flicker_pct"), change = header.indexOf("flicker_change_pct");
        QVERIFY(flips >= 0 && change >= 0);
        for (qsizetype i = 1; i < lines.size(); ++i) {
            const QStringList cells = lines[i].split(',');
            QVERIFY2(cells.value(flips).isEmpty() && cells.value(change).isEmpty(), qPrintable(lines[i]));
        }
        const QJsonArray jsonRows = QJsonDocument::fromJson(json.readAll()).object().value("rows").toArray();
        QCOMPARE(jsonRows.size(), 2);
        for (const QJsonValue& r : jsonRows)
            QVERIFY(r.toObject().value("flicker").toObject().value("flips_pct").isNull());
        QVERIFY(QString::fromUtf8(html.readAll()).contains("Not measured (--flicker-frames 0"));

        for (ReportRow& r : rows) {
            r.flicker.frames = 8;
            r.flicker.flicker = 0.0002;
        }
        writeReport(dir.path(), rows, facts);
        QFile again(dir.filePath("report.csv"));
        QVERIFY(again.open(QIODevice::ReadOnly));
        const QStringList measured = QString::fromUtf8(again.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(measured.at(1).split(',').value(flips), QStringLiteral("0.0200"));
    }

    // One ray a pixel reads every pixel as 0 or 1, so its spread says nothing: the noise floor
    // is unknown there, not 0; from more rays it is given.
    void oneRayAPixelHasNoKnownNoiseFloor()
    {
        std::vector<ReportRow> rows{counted("hard", 40.0, 5.0, 0.3)};
        markParetoFronts(rows);
        for (const int rays : {1, 256}) {
            QTemporaryDir dir;
            ReportFacts facts = seedFacts();
            facts.areaSamplesPerPixel = rays;
            facts.areaNoiseFloor = 0.0;
            writeReport(dir.path(), rows, facts);
            QFile json(dir.filePath("report.json")), html(dir.filePath("report.html"));
            QVERIFY(json.open(QIODevice::ReadOnly) && html.open(QIODevice::ReadOnly));
            const QJsonValue floor = QJsonDocument::fromJson(json.readAll()).object().value("area_noise_floor_pct");
            const QString page = QString::fromUtf8(html.readAll());
            if (rays == 1) {
                QVERIFY(floor.isNull());
                QVERIFY(page.contains("noise floor unknown from one ray a pixel") && page.contains("1 ray per pixel"));
            } else {
                QCOMPARE(floor.toDouble(-1.0), 0.0);
                QVERIFY(page.contains("256 stratified rays per pixel") && page.contains("noise floor 0"));
            }
        }
    }

    void zoomFindsTheErrors()
    {
        QImage errors(400, 200, QImage::Format_RGB32);
        errors.fill(qRgb(100, 100, 100));
        for (int y = 150; y < 160; ++y)
            for (int x = 300; x < 310; ++x)
                errors.setPixel(x, y, (x + y) % 2 ? qRgb(235, 40, 200) : qRgb(40, 220, 235));
        const QImage zoom = zoomOnErrors(errors, 4);
        QCOMPARE(zoom.size(), QSize(400, 200));   // a quarter of each side, four times enlarged
        int coloured = 0;
        for (int y = 0; y < zoom.height(); ++y)
            for (int x = 0; x < zoom.width(); ++x)
                coloured += qRed(zoom.pixel(x, y)) != qGreen(zoom.pixel(x, y)) ? 1 : 0;
        QCOMPARE(coloured, 100 * 16);             // every error pixel, each as a 4 x 4 block

        QImage clean(400, 200, QImage::Format_RGB32);
        clean.fill(qRgb(100, 100, 100));
        QVERIFY(zoomOnErrors(clean).isNull());
    }

    void chartReadsSmallErrorsBesideAnOutlier()
    {
        std::vector<ReportRow> rows{row("defaults", 0.01, 5.0, 0.2), row("tutorial", 0.1, 6.0, 0.2), row("pcf 5", 1.0, 7.0, 0.2),
                                    row("no bias", 41.0, 4.5, 0.2), row("zero", 0.0, 9.0, 0.2)};
        rows[0].defaults = true;
        rows[1].tutorial = true;
        for (int i = 0; i < 12; ++i)   // a crowd of front points near one spot, all wanting labels
            rows.push_back(row(QStringLiteral("crowd %1").arg(i), 0.5 - 0.03 * i, 3.0 + 0.08 * i, 0.02));
        markParetoFronts(rows);
        QTemporaryDir dir;
        ReportFacts facts;
        facts.scene = "seed";
        facts.size = QSize(64, 36);
        writeReport(dir.path(), rows, facts);
        QFile file(dir.filePath("report.html"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(file.readAll());
        const QString svg = page.mid(page.indexOf("<svg"), page.indexOf("</svg>") - page.indexOf("<svg"));

        // Log axis: 0.01 %, 0.1 % and 1 % are evenly spaced, and 41 % fits under the top.
        std::map<QString, double> cy;
        static const QRegularExpression circle(R"re(<circle cx="([\d.]+)" cy="([\d.]+)"[^>]*><title>([^:]+):)re");
        for (auto it = circle.globalMatch(svg); it.hasNext();) {
            const auto m = it.next();
            cy[m.captured(3)] = m.captured(2).toDouble();
        }
        QVERIFY(cy.count("defaults") && cy.count("tutorial") && cy.count("pcf 5") && cy.count("no bias"));
        const double decade = cy["defaults"] - cy["tutorial"];
        QVERIFY2(decade > 60, qPrintable(QString::number(decade)));   // a decade takes a fair share of the height
        QVERIFY(qAbs((cy["tutorial"] - cy["pcf 5"]) - decade) < 0.5);
        QVERIFY(cy["no bias"] < cy["pcf 5"] - decade);
        QVERIFY(svg.contains(">0.01 %<") && svg.contains(">100 %<") && svg.contains("log scale"));
        QVERIFY(cy["zero"] > cy["defaults"] + 10);   // 0 % has its own line below the lowest decade
        QVERIFY(svg.contains(">0 %<"));

        // Labels: the defaults and the tutorial are named; no two labels overlap, nor touch: two
        // labels closer than a few pixels read as one word.
        static const QRegularExpression label(R"re(<text x="([\d.-]+)" y="([\d.-]+)" class="label">([^<]+)</text>)re");
        std::vector<QRectF> boxes;
        QStringList named;
        for (auto it = label.globalMatch(svg); it.hasNext();) {
            const auto m = it.next();
            // A generous width for an 11 px sans-serif font: 6.4 px a character, 10 for a wide
            // one; and a pixel of clearance on each side.
            double width = 0.0;
            for (const QChar c : m.captured(3))
                width += QStringLiteral("mwMW").contains(c) ? 10.0 : 6.4;
            boxes.emplace_back(m.captured(1).toDouble() - 1, m.captured(2).toDouble() - 10, width + 2, 13);
            named << m.captured(3);
        }
        QVERIFY(named.contains("defaults") && named.contains("tutorial"));
        QVERIFY2(named.size() >= 5, qPrintable(named.join(", ")));    // the crowd is labelled where there is room
        for (std::size_t i = 0; i < boxes.size(); ++i)
            for (std::size_t j = i + 1; j < boxes.size(); ++j)
                QVERIFY2(!boxes[i].intersects(boxes[j]), qPrintable(named[qsizetype(i)] + " / " + named[qsizetype(j)]));

        // Percent everywhere: the CSV's error columns are percent and say so.
        QFile csv(dir.filePath("report.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n');
        const QStringList header = lines[0].split(',');
        QVERIFY(header.contains("misclassified_pct") && header.contains("frame_ms") && !header.contains("misclassified"));
        QCOMPARE(lines[4].split(',')[header.indexOf("misclassified_pct")].toDouble(), 41.0);
        // Error images of the defaults and of the tutorial configuration.
        QVERIFY(page.contains("Defaults: defaults") && page.contains("Tutorial configuration: tutorial"));
    }
};

QTEST_GUILESS_MAIN(tst_Report)
#include "tst_Report.moc"
