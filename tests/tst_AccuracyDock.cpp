// The accuracy dock on its own, driven with clicks: a comparison fills the metrics and the
// overlay, acne reads as false shadow, a cancelled trace leaves nothing behind, and the sweep
// plots points that apply their settings when clicked.
#include "AccuracyDock.h"
#include "Application.h"
#include "ErrorPixels.h"
#include "HeadlessTestMain.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QScatterSeries>

#include <array>
#include <memory>

using namespace shadowlab;

namespace {

// A bound on a hang, not a time limit: a sanitizer build sharing two cores with other tests
// took over 60 s for a bias tuning that takes 46 s alone.
constexpr int kTimeoutMs = 180000;
const QSize kViewSize(320, 180);

Settings acneSettings()
{
    Settings s = presetSettings(QStringLiteral("seed"));
    for (const char* a : {"bias.cull_front=false", "bias.footprint=false", "bias.skip_floors=false", "bias.slope=0", "bias.min=0", "filter.mode=hard"})
        applyAssignment(s, QString::fromLatin1(a));
    return s;
}

} // namespace

class TestAccuracyDock : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private:
    QLabel* label(const char* name) const { return m_dock->findChild<QLabel*>(QLatin1String(name)); }
    QPushButton* button(const char* name) const { return m_dock->findChild<QPushButton*>(QLatin1String(name)); }

    // The number at the start of a metric label ("0.42 %", "0.0123"); NaN when there is none.
    double value(const char* name) const
    {
        bool ok = false;
        const double v = label(name)->text().section(QLatin1Char(' '), 0, 0).toDouble(&ok);
        return ok ? v : qQNaN();
    }

    // Clicks Compare and waits until the measurement is in.
    bool compareAndWait()
    {
        QTest::mouseClick(button("compareButton"), Qt::LeftButton);
        return QTest::qWaitFor([&] { return !m_dock->isBusy(); }, kTimeoutMs);
    }

    std::unique_ptr<AccuracyDock> m_dock;

private Q_SLOTS:
    // Each test starts with the dock idle: one that gave up waiting leaves its job running,
    // which would otherwise answer the next test's question with its own settings.
    void init()
    {
        if (m_dock && m_dock->isBusy()) {
            QTest::mouseClick(button("cancelButton"), Qt::LeftButton);
            QVERIFY(QTest::qWaitFor([&] { return !m_dock->isBusy(); }, kTimeoutMs));
        }
    }

    void initTestCase()
    {
        m_dock = std::make_unique<AccuracyDock>();
        m_dock->setAreaSamplesPerAxis(4);
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        m_dock->setViewSize(kViewSize);
        m_dock->resize(340, 900);
        m_dock->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_dock.get()));
        QCOMPARE(m_dock->objectName(), QStringLiteral("accuracyDock"));
        QCOMPARE(m_dock->windowTitle(), QStringLiteral("Accuracy"));
        QCOMPARE(m_dock->measureSize(), kViewSize);
    }

    void measureSizeIsCapped()
    {
        AccuracyDock dock;
        dock.setViewSize(QSize(1920, 1080));
        QCOMPARE(dock.measureSize(), QSize(960, 540));
    }

    void compareShowsMetricsAndOverlay()
    {
        QSignalSpy overlay(m_dock.get(), &AccuracyDock::errorOverlayChanged);
        QVERIFY(qIsNaN(value("misclassifiedValue")));
        QTest::mouseClick(button("compareButton"), Qt::LeftButton);
        QVERIFY(m_dock->isBusy() || !qIsNaN(value("misclassifiedValue")));
        QTRY_VERIFY_WITH_TIMEOUT(!m_dock->isBusy(), kTimeoutMs);

        for (const char* name : {"misclassifiedValue", "falseShadowValue", "falseLightValue", "hardMaeValue", "hardRmseValue",
                                 "areaMaeValue", "areaRmseValue", "noiseFloorValue"}) {
            const double v = value(name);
            QVERIFY2(!qIsNaN(v) && v >= 0.0, qPrintable(QStringLiteral("%1: '%2'").arg(QLatin1String(name), label(name)->text())));
        }
        QVERIFY(value("misclassifiedValue") <= 100.0);
        QVERIFY(value("noiseFloorValue") > 0.0);   // 16 rays per pixel leave visible noise at penumbrae
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("rays/s")), qPrintable(label("referenceInfo")->text()));

        QCOMPARE(overlay.count(), 1);
        QCOMPARE(overlay.last().at(0).toInt(), 0);     // one side: A's view
        const QImage image = overlay.last().at(1).value<QImage>();
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), kViewSize);

        auto* toggle = m_dock->findChild<QCheckBox*>(QStringLiteral("overlayCheck"));
        QTest::mouseClick(toggle, Qt::LeftButton);
        QCOMPARE(overlay.count(), 2);
        QVERIFY(overlay.last().at(1).value<QImage>().isNull());
        QTest::mouseClick(toggle, Qt::LeftButton);
        QCOMPARE(overlay.count(), 3);
        QCOMPARE(overlay.last().at(1).value<QImage>().size(), kViewSize);
        // The heat map of |V - V_ref| in its place, and back: another picture of the same pixels.
        const QImage wrongPixels = overlay.last().at(1).value<QImage>();
        auto* kind = m_dock->findChild<QComboBox*>(QStringLiteral("overlayKind"));
        QVERIFY(kind);
        kind->setCurrentIndex(1);
        QCOMPARE(overlay.count(), 4);
        const QImage heat = overlay.last().at(1).value<QImage>();
        QCOMPARE(heat.size(), kViewSize);
        QVERIFY(heat != wrongPixels);
        QVERIFY2(label("overlayLegend")->text().contains("V_ref"), qPrintable(label("overlayLegend")->text()));
        kind->setCurrentIndex(0);
        QCOMPARE(overlay.count(), 5);
        QVERIFY(overlay.last().at(1).value<QImage>() == wrongPixels);

        // A settings change makes the overlay stale: it goes, and only once.
        Settings moved = presetSettings(QStringLiteral("seed"));
        moved.map.size = 1024;
        m_dock->setSettings(moved);
        QCOMPARE(overlay.count(), 6);
        QVERIFY(overlay.last().at(1).value<QImage>().isNull());
        m_dock->setSettings(moved);
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        QCOMPARE(overlay.count(), 7);              // back to what was measured: shown again
        QVERIFY(!overlay.last().at(1).value<QImage>().isNull());
    }

    // Compare mode: both sides measured over the same pixels, side by side with B − A, each
    // with its own overlay; a change to one side greys that side only.
    void compareModeMeasuresBothSides()
    {
        const Settings a = presetSettings(QStringLiteral("seed"));
        const Settings b = acneSettings();
        QSignalSpy overlay(m_dock.get(), &AccuracyDock::errorOverlayChanged);
        m_dock->setSides(a, b, 1);
        QCOMPARE(button("compareButton")->text(), QStringLiteral("Compare A and B with reference"));
        QCOMPARE(button("tuneButton")->text(), QStringLiteral("Tune bias of side B"));
        QVERIFY(label("misclassifiedValueB")->isVisible() && label("misclassifiedDelta")->isVisible());
        QVERIFY(compareAndWait());

        const double fa = value("falseShadowValue"), fb = value("falseShadowValueB");
        QVERIFY2(fb > 5.0 * fa + 1.0, qPrintable(QStringLiteral("A %1 %, B %2 %").arg(fa).arg(fb)));
        // B − A in percentage points, red: B has more error.
        const QString worse = label("falseShadowDelta")->text();
        QVERIFY2(worse.startsWith(QLatin1Char('+')) && worse.endsWith(QStringLiteral(" pp")), qPrintable(worse));
        QVERIFY2(qAbs(worse.mid(1).section(QLatin1Char(' '), 0, 0).toDouble() - (fb - fa)) < 0.011, qPrintable(worse));
        QVERIFY(label("falseShadowDelta")->styleSheet().contains(QStringLiteral("#c0392b")));
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("same pixels")), qPrintable(label("referenceInfo")->text()));
        // Counts beside the times: B draws the ground into its map, which A leaves out; the
        // same map memory on both sides.
        QVERIFY2(!label("shadowTapsValue")->text().startsWith(QStringLiteral("—")) && label("shadowTapsValue")->text() != QStringLiteral("0"),
                 qPrintable(label("shadowTapsValue")->text()));
        QVERIFY2(label("shadowSamplesDelta")->text().startsWith(QLatin1Char('+')), qPrintable(label("shadowSamplesDelta")->text()));
        QCOMPARE(label("mapMemoryDelta")->text(), QStringLiteral("same"));

        // Each side's overlay, of the same pixels; the acne is B's.
        std::array<QImage, 2> last;
        for (const QList<QVariant>& args : overlay)
            last[std::size_t(args.at(0).toInt())] = args.at(1).value<QImage>();
        QVERIFY(!last[0].isNull() && !last[1].isNull());
        QCOMPARE(last[0].size(), kViewSize);
        QCOMPARE(last[1].size(), kViewSize);
        QVERIFY2(falseShadowPixels(last[1]) > 10 * (falseShadowPixels(last[0]) + 1), qPrintable(QStringLiteral("%1 %2").arg(falseShadowPixels(last[0])).arg(falseShadowPixels(last[1]))));

        // Swapped: the same numbers in the other columns (the reference is reused), the
        // difference negative and green.
        m_dock->setSides(b, a, 0);
        QCOMPARE(button("tuneButton")->text(), QStringLiteral("Tune bias of side A"));
        QVERIFY(compareAndWait());
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("reused")), qPrintable(label("referenceInfo")->text()));
        QCOMPARE(value("falseShadowValue"), fb);
        QCOMPARE(value("falseShadowValueB"), fa);
        QVERIFY2(label("falseShadowDelta")->text().startsWith(QChar(0x2212)), qPrintable(label("falseShadowDelta")->text()));
        QVERIFY(label("falseShadowDelta")->styleSheet().contains(QStringLiteral("#2e8b3e")));

        // A change to B greys B's column and withdraws B's overlay only.
        overlay.clear();
        Settings smaller = a;
        smaller.map.size = 512;
        m_dock->setSides(b, smaller, 1);
        QVERIFY(label("falseShadowValue")->isEnabled());
        QVERIFY(!label("falseShadowValueB")->isEnabled());
        QVERIFY(!label("falseShadowDelta")->isEnabled());
        QCOMPARE(overlay.count(), 1);
        QCOMPARE(overlay.last().at(0).toInt(), 1);
        QVERIFY(overlay.last().at(1).value<QImage>().isNull());
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("Side B changed")), qPrintable(label("referenceInfo")->text()));

        // Lights placed differently on the two sides: a reference each.
        Settings left = a, right = a;
        left.light.position += glm::dvec3(-0.7, 0.0, 0.4);
        right.light.position += glm::dvec3(0.8, 0.5, -0.3);
        m_dock->setSides(left, right, 0);
        QVERIFY(compareAndWait());
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("2 references traced")), qPrintable(label("referenceInfo")->text()));
        for (const char* name : {"misclassifiedValue", "misclassifiedValueB", "areaMaeValue", "areaMaeValueB"})
            QVERIFY2(value(name) >= 0.0, qPrintable(label(name)->text()));

        // The same settings on both sides: every difference is "same".
        m_dock->setSides(a, a, 1);
        QVERIFY(compareAndWait());
        for (const char* name : {"misclassifiedDelta", "falseShadowDelta", "falseLightDelta", "hardMaeDelta", "hardRmseDelta",
                                 "flickerDelta", "areaMaeDelta", "areaRmseDelta", "noiseFloorDelta"})
            QVERIFY2(label(name)->text() == QStringLiteral("same"), qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(name), label(name)->text())));

        // Back to one side: B's column hides and its overlay goes.
        overlay.clear();
        m_dock->setSettings(a);
        QVERIFY(!label("misclassifiedValueB")->isVisible() && !label("misclassifiedDelta")->isVisible());
        QCOMPARE(button("compareButton")->text(), QStringLiteral("Compare with reference"));
        QVERIFY(!qIsNaN(value("misclassifiedValue")));
        QCOMPARE(overlay.count(), 1);
        QCOMPARE(overlay.last().at(0).toInt(), 1);
        QVERIFY(overlay.last().at(1).value<QImage>().isNull());
    }

    // The frames' cost beside the error: medians, B − A, and "same" within the timing spread.
    void frameTimesShowBesideTheError()
    {
        const auto history = [](double frameMs, double shadowMs, bool shadowDrawn) {
            FrameTimeHistory h;
            for (int i = 0; i < 30; ++i) {
                FrameStats f;
                f.frameWallMs = frameMs + (i % 5) * 0.1;    // a small spread
                f.shadowPassWallMs = shadowMs;
                f.shadowPassRendered = shadowDrawn;
                h.add(f);
            }
            return h.summary();
        };
        m_dock->setSides(presetSettings(QStringLiteral("seed")), acneSettings(), 0);
        m_dock->setFrameTimes({history(10.0, 4.0, true), history(25.0, 4.0, false)}, true);
        QCOMPARE(value("frameTimeValue"), 10.2);
        QCOMPARE(value("frameTimeValueB"), 25.2);
        QCOMPARE(label("frameTimeDelta")->text(), QStringLiteral("+15.0 ms"));
        QCOMPARE(label("shadowPassTimeValueB")->text(), QStringLiteral("cached"));
        QVERIFY2(label("costInfo")->text().contains(QStringLiteral("CPU time")), qPrintable(label("costInfo")->text()));
        m_dock->setFrameTimes({history(10.0, 4.0, true), history(10.1, 4.0, true)}, false);
        QCOMPARE(label("frameTimeDelta")->text(), QStringLiteral("same"));
        QCOMPARE(label("shadowPassTimeDelta")->text(), QStringLiteral("same"));
        QVERIFY(!label("costInfo")->text().contains(QStringLiteral("CPU time")));
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        m_dock->setFrameTimes({history(12.0, 4.0, true)}, true);
        QCOMPARE(value("frameTimeValue"), 12.2);
        QVERIFY(!label("frameTimeValueB")->isVisible());

        // Too few frames since a side's settings changed to tell a difference from noise.
        const auto frames = [](std::vector<double> frameMs, int shadowEvery) {
            FrameTimeHistory h;
            for (std::size_t i = 0; i < frameMs.size(); ++i) {
                FrameStats f;
                f.frameWallMs = frameMs[i];
                f.shadowPassRendered = shadowEvery > 0 && i % std::size_t(shadowEvery) == 0;
                f.shadowPassWallMs = f.shadowPassRendered ? frameMs[i] * 0.6 : 0.0;
                h.add(f);
            }
            return h.summary();
        };
        m_dock->setSides(presetSettings(QStringLiteral("seed")), acneSettings(), 0);
        m_dock->setFrameTimes({frames({17.4, 17.2, 17.6}, 1), frames(std::vector<double>(30, 5.8), 1)}, true);
        QCOMPARE(label("frameTimeDelta")->text(), QStringLiteral("…"));
        // A pass that ran in some frames only: its median is of those, and the dock says so.
        std::vector<double> mixed(30, 6.0);
        for (std::size_t i = 0; i < mixed.size(); i += 10)
            mixed[i] = 20.0;
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        m_dock->setFrameTimes({frames(mixed, 10)}, true);
        QCOMPARE(value("shadowPassTimeValue"), 12.0);
        QCOMPARE(value("frameTimeValue"), 6.0);
        QVERIFY2(label("costInfo")->text().contains(QStringLiteral("3 of 30 frames")) && label("costInfo")->text().contains(QStringLiteral("20.0 ms")),
                 qPrintable(label("costInfo")->text()));
        QVERIFY2(FrameTimeHistory::text(frames(mixed, 10), true).contains(QStringLiteral("shadow 12.0 in 3 of 30")),
                 qPrintable(FrameTimeHistory::text(frames(mixed, 10), true)));
    }

    void acneReadsAsFalseShadow()
    {
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        QVERIFY(compareAndWait());
        const double defaults = value("falseShadowValue");
        m_dock->setSettings(acneSettings());
        QVERIFY(compareAndWait());
        const double acne = value("falseShadowValue");
        QVERIFY2(label("referenceInfo")->text().contains(QStringLiteral("reused")), qPrintable(label("referenceInfo")->text()));
        QVERIFY2(acne > 5.0 * defaults + 1.0, qPrintable(QStringLiteral("acne %1 %, defaults %2 %").arg(acne).arg(defaults)));
        QVERIFY(value("falseShadowValue") <= value("misclassifiedValue"));
    }

    void cancelDiscardsTheTrace()
    {
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        m_dock->setViewSize(QSize(300, 200));   // another size: the cached reference does not apply
        QTest::mouseClick(button("compareButton"), Qt::LeftButton);
        QVERIFY(m_dock->isBusy());
        QTest::mouseClick(button("cancelButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!m_dock->isBusy(), kTimeoutMs);
        QVERIFY2(label("status")->text().contains(QStringLiteral("Cancelled")), qPrintable(label("status")->text()));

        QVERIFY(compareAndWait());
        const QString info = label("referenceInfo")->text();
        QVERIFY2(info.contains(QStringLiteral("traced")) && info.startsWith(QStringLiteral("300×200")), qPrintable(info));
        QVERIFY(!qIsNaN(value("misclassifiedValue")));
        m_dock->setViewSize(kViewSize);
    }

    void invalidSettingsShowAMessage()
    {
        Settings bad = presetSettings(QStringLiteral("seed"));
        bad.light.farPlane = bad.light.nearPlane;
        m_dock->setSettings(bad);
        QTest::mouseClick(button("compareButton"), Qt::LeftButton);
        QVERIFY(!m_dock->isBusy());
        QVERIFY2(label("status")->text().contains(QStringLiteral("light.")), qPrintable(label("status")->text()));
    }

    void sweepPlotsPointsThatApply()
    {
        // Front faces in the map, so that the "no bias" variation shows acne.
        Settings current = presetSettings(QStringLiteral("seed"));
        current.bias.cullFront = false;
        m_dock->setSettings(current);
        QSignalSpy apply(m_dock.get(), &AccuracyDock::applySettingsRequested);
        QTest::mouseClick(button("sweepButton"), Qt::LeftButton);
        QVERIFY(m_dock->isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(!m_dock->isBusy(), kTimeoutMs);

        auto* view = m_dock->findChild<QChartView*>(QStringLiteral("sweepChart"));
        QVERIFY(view);
        const QList<QAbstractSeries*> series = view->chart()->series();
        QCOMPARE(series.size(), 3);
        auto* variations = qobject_cast<QScatterSeries*>(series[0]);
        auto* marker = qobject_cast<QScatterSeries*>(series[1]);
        auto* wrong = qobject_cast<QScatterSeries*>(series[2]);     // rings over visibly wrong pictures
        QVERIFY2(variations->count() >= 8, qPrintable(QString::number(variations->count())));
        QCOMPARE(marker->count(), 1);
        for (const QPointF& p : variations->points())
            QVERIFY(p.x() > 0.0 && p.y() >= 0.0);

        // Click the point that is highest (most error): surely not the current settings.
        QPointF target = variations->at(0);
        for (const QPointF& p : variations->points()) {
            if (p.y() > target.y())
                target = p;
        }
        QVERIFY(target != marker->at(0));
        const QPoint at = view->mapFromScene(view->chart()->mapToScene(view->chart()->mapToPosition(target, variations)));
        // Sent directly: QTest::mouseMove moves the cursor, which the headless platform has not.
        QMouseEvent move(QEvent::MouseMove, at, view->viewport()->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(view->viewport(), &move);
        QTRY_VERIFY(label("pointInfo")->text().contains(QStringLiteral("Click to apply")));
        QVERIFY(label("pointInfo")->text().contains(QStringLiteral("no bias")));   // the highest error
        // Acne everywhere: its picture is visibly wrong, ringed, and the note says why.
        QVERIFY(wrong->points().contains(target));
        QVERIFY(wrong->count() < variations->count());
        QVERIFY2(label("pointInfo")->text().contains(QStringLiteral("visibly wrong: DSSIM")), qPrintable(label("pointInfo")->text()));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
        QTRY_COMPARE(apply.count(), 1);
        const Settings chosen = apply.last().at(0).value<Settings>();
        QVERIFY(chosen != current);

        // Applying it moves the current marker there.
        m_dock->setSettings(chosen);
        QCOMPARE(marker->count(), 1);
        QCOMPARE(marker->at(0), target);

        // Another scene withdraws the seed's sweep and measurement: nothing left to click.
        QVERIFY(!qIsNaN(value("misclassifiedValue")));
        m_dock->setSettings(presetSettings(QStringLiteral("torus")));
        QCOMPARE(qobject_cast<QScatterSeries*>(view->chart()->series().at(0))->count(), 0);
        QVERIFY(qIsNaN(value("misclassifiedValue")));
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
    }

    void sweepCancels()
    {
        QTest::mouseClick(button("sweepButton"), Qt::LeftButton);
        QVERIFY(m_dock->isBusy());
        QTest::mouseClick(button("cancelButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!m_dock->isBusy(), kTimeoutMs);
        QVERIFY2(label("status")->text().contains(QStringLiteral("cancelled")), qPrintable(label("status")->text()));
        auto* view = m_dock->findChild<QChartView*>(QStringLiteral("sweepChart"));
        QVERIFY(qobject_cast<QScatterSeries*>(view->chart()->series().at(0))->count() < 8);
        QVERIFY(button("sweepButton")->isEnabled());
    }

    // Tune bias on acne (front faces, no bias): the button runs without blocking, draws the
    // trade-off, and Apply hands on the settings with the bias it found, which removes the acne.
    void tuneBiasFindsAndAppliesTheFix()
    {
        m_dock->setSettings(acneSettings());
        QVERIFY(!button("applyTuningButton")->isEnabled());
        QTest::mouseClick(button("tuneButton"), Qt::LeftButton);
        QVERIFY(m_dock->isBusy());
        QVERIFY(!button("tuneButton")->isEnabled());
        QVERIFY(QTest::qWaitFor([&] { return !m_dock->isBusy(); }, kTimeoutMs));
        QVERIFY2(button("applyTuningButton")->isEnabled(), qPrintable(label("status")->text()));
        QVERIFY(m_dock->findChild<QWidget*>(QStringLiteral("tuningChart"))->isVisible());
        QVERIFY2(label("status")->text().contains(QStringLiteral("Best bias")), qPrintable(label("status")->text()));

        QSignalSpy apply(m_dock.get(), &AccuracyDock::applySettingsRequested);
        QTest::mouseClick(button("applyTuningButton"), Qt::LeftButton);
        QCOMPARE(apply.count(), 1);
        const Settings tuned = apply.front().front().value<Settings>();
        QVERIFY(tuned.bias.slope > 0.0 || tuned.bias.min > 0.0);
        QCOMPARE(tuned.bias.cullFront, false);      // only the bias changes

        // Measured: the tuned bias has a small fraction of the acne of none.
        QVERIFY(compareAndWait());
        const double before = value("falseShadowValue");
        m_dock->setSettings(tuned);
        QVERIFY(compareAndWait());
        const double after = value("falseShadowValue");
        QVERIFY2(after < 0.2 * before, qPrintable(QString("false shadow %1 -> %2").arg(before).arg(after)));
        QVERIFY(button("applyTuningButton")->isEnabled());

        // The tuning was of the seed: on another scene there is nothing to apply.
        m_dock->setSettings(presetSettings(QStringLiteral("torus")));
        QVERIFY(!button("applyTuningButton")->isEnabled());
        QVERIFY(!m_dock->findChild<QWidget*>(QStringLiteral("tuningChart"))->isVisible());
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
    }

    // The defaults are on the knee: the tuner says so, draws its curve, and offers nothing to
    // apply; the figures it quotes say what they are the mean of.
    void tuningTheDefaultsOffersNothingToApply()
    {
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        QTest::mouseClick(button("tuneButton"), Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&] { return !m_dock->isBusy(); }, kTimeoutMs));
        const QString status = label("status")->text();
        QVERIFY2(status.contains(QStringLiteral("already on the knee")) && status.contains(QStringLiteral("light directions")), qPrintable(status));
        QVERIFY(m_dock->findChild<QWidget*>(QStringLiteral("tuningChart"))->isVisible());
        QVERIFY(!button("applyTuningButton")->isEnabled());
    }
};

SHADOWLAB_TEST_MAIN(TestAccuracyDock)
#include "tst_AccuracyDock.moc"
