// The accuracy dock on its own, driven with clicks: a comparison fills the metrics and the
// overlay, acne reads as false shadow, a cancelled trace leaves nothing behind, and the sweep
// plots points that apply their settings when clicked.
#include "AccuracyDock.h"
#include "Application.h"
#include "HeadlessTestMain.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QScatterSeries>

#include <memory>

using namespace shadowlab;

namespace {

constexpr int kTimeoutMs = 60000;
const QSize kViewSize(320, 180);

Settings acneSettings()
{
    Settings s = presetSettings(QStringLiteral("seed"));
    for (const char* a : {"bias.cull_front=false", "bias.slope=0", "bias.min=0", "filter.mode=hard"})
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
        const QImage image = overlay.last().at(0).value<QImage>();
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), kViewSize);

        auto* toggle = m_dock->findChild<QCheckBox*>(QStringLiteral("overlayCheck"));
        QTest::mouseClick(toggle, Qt::LeftButton);
        QCOMPARE(overlay.count(), 2);
        QVERIFY(overlay.last().at(0).value<QImage>().isNull());
        QTest::mouseClick(toggle, Qt::LeftButton);
        QCOMPARE(overlay.count(), 3);
        QCOMPARE(overlay.last().at(0).value<QImage>().size(), kViewSize);

        // A settings change makes the overlay stale: it goes, and only once.
        Settings moved = presetSettings(QStringLiteral("seed"));
        moved.map.size = 1024;
        m_dock->setSettings(moved);
        QCOMPARE(overlay.count(), 4);
        QVERIFY(overlay.last().at(0).value<QImage>().isNull());
        m_dock->setSettings(moved);
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
        QCOMPARE(overlay.count(), 5);              // back to what was measured: shown again
        QVERIFY(!overlay.last().at(0).value<QImage>().isNull());
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
        QCOMPARE(series.size(), 2);
        auto* variations = qobject_cast<QScatterSeries*>(series[0]);
        auto* marker = qobject_cast<QScatterSeries*>(series[1]);
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
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
        QTRY_COMPARE(apply.count(), 1);
        const Settings chosen = apply.last().at(0).value<Settings>();
        QVERIFY(chosen != current);

        // Applying it moves the current marker there.
        m_dock->setSettings(chosen);
        QCOMPARE(marker->count(), 1);
        QCOMPARE(marker->at(0), target);
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
        m_dock->setSettings(presetSettings(QStringLiteral("seed")));
    }
};

SHADOWLAB_TEST_MAIN(TestAccuracyDock)
#include "tst_AccuracyDock.moc"
