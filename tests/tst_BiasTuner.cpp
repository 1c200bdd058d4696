// The bias tuner against the ray-traced reference: its trade-off curve trades acne for leaks
// and nothing else, it finds the fix when there is acne to fix, and the default bias sits on
// the knee of every preset's curve, so the tuner recommends no change there.
#include "Application.h"
#include "BiasTuner.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QtTest>

using namespace shadowlab;

namespace {

BiasTuning tune(HeadlessRenderer& headless, const Settings& settings)
{
    BiasTuner tuner(settings, QSize(160, 90));
    while (!tuner.done())
        tuner.step(headless.renderer());
    return tuner.result();
}

} // namespace

class TestBiasTuner : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    void defaultsSitOnTheKnee_data()
    {
        QTest::addColumn<QString>("scene");
        for (const QString& name : sceneNames())
            QTest::newRow(qPrintable(name)) << name;
    }

    void defaultsSitOnTheKnee()
    {
        QFETCH(QString, scene);
        const BiasTuning t = tune(*m_headless, presetSettings(scene));
        QVERIFY(t.placements.size() >= 5);
        QVERIFY(!t.front.empty());
        // The curve: more false shadow buys strictly less false light, point by point.
        for (std::size_t i = 1; i < t.front.size(); ++i) {
            QCOMPARE_GT(t.candidates[t.front[i]].falseShadow, t.candidates[t.front[i - 1]].falseShadow);
            QCOMPARE_LT(t.candidates[t.front[i]].falseLight, t.candidates[t.front[i - 1]].falseLight);
        }
        const BiasCandidate& best = t.candidates[t.best];
        qInfo("%s: defaults misclassify %.4f %%, the best of the grid (%g/%g) %.4f %%", qPrintable(scene), 100 * t.current.misclassified(),
              best.slope, best.min, 100 * best.misclassified());
        QVERIFY(std::find(t.front.begin(), t.front.end(), t.best) != t.front.end());   // a point of the curve shown
        // Nothing beyond the error noise to gain, so nothing to recommend.
        QVERIFY2(!t.improves, qPrintable(QStringLiteral("%1 px as set, %2 px at best").arg(t.current.misclassifiedPixels).arg(best.misclassifiedPixels)));
    }

    // Front faces in the map and no bias: acne everywhere; the tuner finds a bias that removes
    // it, and applying what it found measures as it said.
    void findsTheBiasThatRemovesAcne_data()
    {
        QTest::addColumn<QString>("space");
        for (const QString& space : findSettingKey("bias.space")->choices)
            QTest::newRow(qPrintable(space)) << space;
    }

    void findsTheBiasThatRemovesAcne()
    {
        QFETCH(QString, space);
        Settings s = presetSettings("seed");
        applySetting(s, "bias.cull_front", "false");
        applySetting(s, "bias.footprint", "false");
        applySetting(s, "bias.skip_floors", "false");
        applySetting(s, "bias.space", space);
        s.bias.slope = 0.0;
        s.bias.min = 0.0;
        const BiasTuning t = tune(*m_headless, s);
        const BiasCandidate& best = t.candidates[t.best];
        qInfo("%s: no bias %.3f %% false shadow; best %g/%g: %.4f %% false shadow, %.4f %% false light", qPrintable(space),
              100 * t.current.falseShadow, best.slope, best.min, 100 * best.falseShadow, 100 * best.falseLight);
        QCOMPARE_GT(t.current.falseShadow, 0.01);
        QCOMPARE_LT(best.misclassified(), 0.1 * t.current.misclassified());
        QVERIFY(best.slope > 0.0 || best.min > 0.0);
        QVERIFY(t.improves);
        QVERIFY(std::find(t.front.begin(), t.front.end(), t.best) != t.front.end());
    }

    // A current setting on the grid is that very candidate, measured once: what is quoted "as
    // set" and what the table shows for it are one number.
    void currentOnTheGridIsThatCandidate()
    {
        Settings s = presetSettings("seed");
        s.bias.space = BiasSpace::World;
        s.bias.slope = 0.05;
        s.bias.min = 0.002;
        BiasTuner tuner(s, QSize(96, 54));
        const int steps = tuner.steps();
        while (!tuner.done())
            tuner.step(m_headless->renderer());
        const BiasTuning t = tuner.result();
        QCOMPARE(steps, int(t.candidates.size() * t.placements.size()));   // not measured a second time
        QVERIFY(t.currentCandidate.has_value());
        const BiasCandidate& c = t.candidates[*t.currentCandidate];
        QCOMPARE(c.slope, 0.05);
        QCOMPARE(c.min, 0.002);
        QCOMPARE(t.current.misclassifiedPixels, c.misclassifiedPixels);
        QCOMPARE(t.current.falseShadow, c.falseShadow);
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestBiasTuner)
#include "tst_BiasTuner.moc"
