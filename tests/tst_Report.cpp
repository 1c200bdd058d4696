// The report as its reader meets it: which configurations make the front (and that timing noise
// does not change that), lights kept apart, identical configurations measured once, an error
// axis that keeps small errors readable beside a large one, labels that do not cover each
// other, and error images zoomed where the errors are. No GL: rows are made by hand.
#include "ReportSweep.h"
#include "ReportWriter.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QFile>
#include <QImage>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <map>

using namespace shadowlab;

namespace {

ReportRow row(const QString& label, double errorPercent, double medianMs, double spreadMs, const QString& light = QStringLiteral("ortho light"))
{
    ReportRow r;
    r.label = label;
    r.light = light;
    r.frame.count = 30;
    r.frame.median = medianMs;
    r.frame.p10 = medianMs - spreadMs;
    r.frame.p90 = medianMs + spreadMs;
    r.accuracy.hard.misclassified = errorPercent / 100.0;
    r.accuracy.area.mae = errorPercent / 200.0;
    QImage errors(64, 36, QImage::Format_RGB32);
    errors.fill(qRgb(90, 90, 90));
    r.accuracy.hardErrors = errors;
    return r;
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
    void frontHoldsUnderTimingNoise()
    {
        // fast/rough and slow/exact are the classic trade-off; "twin" is as fast as "exact"
        // within the noise but less accurate; "clone" has exact's error and is clearly slower.
        std::vector<ReportRow> rows{row("fast", 8.0, 4.0, 0.3), row("exact", 0.5, 10.0, 1.0), row("twin", 0.6, 9.7, 1.0),
                                    row("clone", 0.5, 14.0, 0.5), row("middle", 2.0, 6.0, 0.4)};
        markParetoFront(rows);
        const QStringList expected{"exact", "fast", "middle"};
        QCOMPARE(front(rows), expected);
        // The medians wander within their spreads from run to run: the front stays.
        QRandomGenerator random(7);
        for (int run = 0; run < 200; ++run) {
            std::vector<ReportRow> noisy = rows;
            for (ReportRow& r : noisy) {
                const double spread = r.frame.p90 - r.frame.p10;
                r.frame.median = r.frame.p10 + random.generateDouble() * spread;
            }
            markParetoFront(noisy);
            QCOMPARE(front(noisy), expected);
        }
    }

    void clearlyFasterWithTheSameErrorWins()
    {
        std::vector<ReportRow> rows{row("slow", 1.0, 10.0, 0.5), row("quick", 1.0, 5.0, 0.5)};
        markParetoFront(rows);
        QCOMPARE(front(rows), QStringList{"quick"});
    }

    void eachLightHasItsOwnFront()
    {
        // Grazing light: every configuration is worse and slower than under the overhead one,
        // yet the best of them is on its light's front.
        std::vector<ReportRow> rows{row("overhead fast", 1.0, 4.0, 0.2, "overhead"), row("overhead slow", 0.2, 9.0, 0.2, "overhead"),
                                    row("grazing a", 12.0, 11.0, 0.2, "grazing"), row("grazing b", 20.0, 12.0, 0.2, "grazing")};
        markParetoFront(rows);
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
            const std::vector<SweepEntry> entries = loadSweep(name);
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
        markParetoFront(rows);
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

        // Labels: the defaults and the tutorial are named; no two labels overlap.
        static const QRegularExpression label(R"re(<text x="([\d.-]+)" y="([\d.-]+)" class="label">([^<]+)</text>)re");
        std::vector<QRectF> boxes;
        QStringList named;
        for (auto it = label.globalMatch(svg); it.hasNext();) {
            const auto m = it.next();
            // A generous width for an 11 px sans-serif font: 6.4 px a character.
            boxes.emplace_back(m.captured(1).toDouble(), m.captured(2).toDouble() - 10, 6.4 * m.captured(3).size(), 13);
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
