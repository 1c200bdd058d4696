// Scenes that move, against the Embree reference at every instant: shadows of moving casters
// are where the ray tracer says at each time, under every light type; a frame is a function of
// its settings (the time included) whatever was drawn before; a still scene does no work for a
// clock; and a tracer moved to another instant traces what a fresh one does.
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "Measurement.h"
#include "RayTracer.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace shadowlab;

namespace {

const QSize kSize(320, 180);

// Shapes of every kind of motion over a floor, with a still box: written for the test.
const QByteArray kMovingShapes = R"({ "shapes": [
    { "shape": "ground", "height": 0, "size": 12 },
    { "name": "still", "shape": "cube", "position": [2.5, 0.5, -1.5], "scale": 0.5 },
    { "name": "spinner", "shape": "cube", "position": [0, 1.2, 0], "scale": [1.5, 0.08, 0.3], "motion": { "type": "spin", "period": 4 } },
    { "name": "orbiter", "shape": "sphere", "position": [2, 0.9, 0], "scale": 0.35, "motion": { "type": "orbit", "centre": [0, 0, 0], "speed": -45 } },
    { "name": "bobber", "shape": "torus", "position": [-2, 1.2, 1], "scale": 0.5, "motion": { "type": "bob", "amplitude": 0.6, "period": 3 } },
    { "name": "driver", "shape": "pyramid", "position": [-2, 0.6, -2], "scale": 0.4, "motion": { "type": "path", "smooth": true, "keys": [
        { "time": 0 }, { "time": 2, "position": [0, 0.6, -2.5], "rotation": { "angle": 90, "axis": [0, 1, 0] } }, { "time": 4, "position": [-2, 0.6, -2] } ] } }
  ],
  "light.position": [-4, 8, 3], "light.target": [0, 0, 0],
  "camera.position": [0, 6, 8], "camera.target": [0, 0.3, 0] })";

int wrong(const probe::Agreement& a) { return a.falseShadow + a.falseLight; }

} // namespace

class TestAnimation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QFile file(m_dir.filePath(QStringLiteral("moving.json")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kMovingShapes);
        m_moving = file.fileName();
        m_headless = std::make_unique<HeadlessRenderer>();
    }
    void cleanupTestCase() { m_headless.reset(); }

    void shadowsFollowMovingCasters_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        for (const char* light : {"directional", "spot", "point"}) {
            QTest::addRow("swing, %s", light) << QStringLiteral("swing") << QStringList{QStringLiteral("light.type=%1").arg(light)};
            QTest::addRow("every motion, %s", light) << QStringLiteral("moving") << QStringList{QStringLiteral("light.type=%1").arg(light)};
        };
        QTest::addRow("swing, pcf 5x5") << QStringLiteral("swing") << QStringList{QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=5")};
        QTest::addRow("every motion, 3 cascades") << QStringLiteral("moving") << QStringList{QStringLiteral("shadow.cascades=3")};
        QTest::addRow("every motion, virtual") << QStringLiteral("moving") << QStringList{QStringLiteral("shadow.virtual=true")};
        QTest::addRow("city traffic") << QStringLiteral("city:600+400")
                                      << QStringList{QStringLiteral("camera.position=-3,8,45"), QStringLiteral("camera.target=0,0,-20")};
    }
    // At four instants of the clip, the shadows agree with a reference traced at that instant,
    // and they are not the same shadows each time (the casters did move them).
    void shadowsFollowMovingCasters()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        const QString name = scene == u"moving" ? m_moving : scene;
        Settings s = presetSettings(name);
        for (const QString& a : assignments)
            applyAssignment(s, a);
        const double clip = buildScene(name).clipLength();
        QVERIFY(clip > 0.0);
        Renderer& r = m_headless->renderer();
        std::vector<std::vector<float>> shadows;
        for (int i = 0; i < 4; ++i) {
            s.animation.time = clip * (0.1 + 0.2 * i);
            const VisibilityBuffer buffer = probe::visibility(r, s, kSize);
            const std::vector<float> hard = probe::hardReference(r, buffer);
            const probe::Agreement a = probe::agreement(buffer, hard, r.lightFrame());
            qInfo("%s at %.2f s: %s", qPrintable(QTest::currentDataTag()), s.animation.time, qPrintable(probe::describe(a)));
            QVERIFY2(a.referenceShadowed > 100, qPrintable(probe::describe(a)));
            // As right as the same casters standing still where they are at that instant (the
            // bound's base: the map's resolution on the scene), within 0.1 % of the pixels.
            Scene frozen = buildScene(name);
            frozen.poseAt(s.animation.time);
            for (SceneObject& object : frozen.objects)
                object.motion.reset();
            r.setScene(std::move(frozen));
            const int base = wrong(probe::agreement(r, s, kSize));
            r.setScene(std::nullopt);
            QVERIFY2(wrong(a) <= base + base / 4 + std::max(3, a.counted / 1000),
                     qPrintable(probe::describe(a) + QStringLiteral("; standing still there: %1").arg(base)));
            shadows.push_back(hard);
        }
        for (std::size_t i = 1; i < shadows.size(); ++i) {
            int changed = 0;
            for (std::size_t p = 0; p < shadows[i].size(); ++p)
                changed += (shadows[i][p] < 0.5f) != (shadows[i - 1][p] < 0.5f);
            QVERIFY2(changed > 20, qPrintable(QStringLiteral("instant %1: %2 pixels changed").arg(i).arg(changed)));
        }
    }

    // The frame at a time is the same whether the renderer came from another time or is fresh.
    void aFrameIsAFunctionOfItsTime_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("pcf") << QStringList{};
        QTest::newRow("vsm") << QStringList{QStringLiteral("filter.mode=vsm")};
        QTest::newRow("point light") << QStringList{QStringLiteral("light.type=point")};
        QTest::newRow("cascades") << QStringList{QStringLiteral("shadow.cascades=3")};
    }
    void aFrameIsAFunctionOfItsTime()
    {
        QFETCH(QStringList, assignments);
        Settings s = presetSettings(m_moving);
        for (const QString& a : assignments)
            applyAssignment(s, a);
        Renderer& r = m_headless->renderer();
        s.animation.time = 2.7;
        const QImage there = m_headless->renderScene(s, kSize);
        s.animation.time = 0.4;
        m_headless->renderScene(s, kSize);
        const QImage before = m_headless->renderScene(s, kSize);
        s.animation.time = 2.7;
        const QImage back = m_headless->renderScene(s, kSize);
        QVERIFY(r.lastFrame().shadowPassRendered);
        QCOMPARE(back, there);
        QVERIFY(before != there);
    }

    // The light is fitted to everywhere the moving casters go: while they move, the map's volume
    // and texel grid stand still, so the still casters' shadows do not swim.
    void theMapStandsStillWhileCastersMove_data()
    {
        QTest::addColumn<QString>("light");
        QTest::newRow("directional") << QStringLiteral("directional");
        QTest::newRow("spot") << QStringLiteral("spot");
    }
    void theMapStandsStillWhileCastersMove()
    {
        QFETCH(QString, light);
        Settings s = presetSettings(m_moving);
        applyAssignment(s, QStringLiteral("light.type=") + light);
        Renderer& r = m_headless->renderer();
        s.animation.time = 0.5;
        probe::visibility(r, s, kSize);
        const glm::dmat4 first = r.lightFrame().shadowMatrix;
        const int fits = r.fitCount();
        for (const double t : {1.3, 2.9, 5.1}) {
            s.animation.time = t;
            probe::visibility(r, s, kSize);
            QVERIFY(r.lastFrame().shadowPassRendered);
            QCOMPARE(r.lightFrame().shadowMatrix, first);
        }
        // Fitted to everywhere the casters go, the views are not fitted again while they move:
        // only where the casters are now is found again.
        QCOMPARE(r.fitCount(), fits);
    }

    // On a still scene the clock changes nothing: no refit, no shadow pass, the same picture.
    void aStillSceneIgnoresTheClock()
    {
        Settings s = presetSettings(QStringLiteral("seed"));
        Renderer& r = m_headless->renderer();
        const QImage first = m_headless->renderScene(s, kSize);
        m_headless->renderScene(s, kSize);
        const int fits = r.fitCount();
        s.animation.time = 5.5;
        s.animation.play = true;
        const QImage later = m_headless->renderScene(s, kSize);
        QVERIFY(!r.lastFrame().shadowPassRendered);
        QCOMPARE(r.fitCount(), fits);
        QCOMPARE(later, first);
    }

    // A gliding caster's hard shadow steps over the map's texel grid: flips at still receivers
    // that the reference does not have. A finer map steps less; the shadow's own motion (which
    // the reference shares) is not counted.
    void flickerInTimeFallsWithFinerMaps()
    {
        Settings s = presetSettings(QStringLiteral("swing"));
        applyAssignment(s, QStringLiteral("filter.mode=hard"));
        std::vector<double> times;
        for (int i = 0; i < 12; ++i)
            times.push_back(0.2 + i / 60.0);
        Renderer& r = m_headless->renderer();
        std::vector<double> flicker;
        for (const int size : {256, 1024, 4096}) {
            s.map.size = size;
            const FlickerResult f = measureTimeFlicker(r, s, times, kSize);
            qInfo("map %d: flicker in time %.4f %% (worst pair %.4f %%), %d pixels", size, 100 * f.flicker, 100 * f.worstPair, f.pixels);
            QVERIFY(f.measured());
            flicker.push_back(f.flicker);
        }
        QVERIFY2(flicker[0] > 0.0, "a coarse map's shadow steps as its caster glides");
        QVERIFY(flicker[0] > flicker[1] && flicker[1] >= flicker[2]);
        // The shadow itself moves over many pixels a frame; nearly none of that is flicker.
        std::vector<VisibilityBuffer> frames;
        for (double t : times) {
            s.animation.time = t;
            frames.push_back(probe::visibility(r, s, kSize));
        }
        QVERIFY(measureFlicker(frames).flicker > 5 * flicker[2]);
    }

    // A tracer whose instances moved to another time answers as one made at that time.
    void aMovedTracerTracesAsAFreshOne()
    {
        Scene scene = buildScene(m_moving);
        scene.poseAt(0.3);
        RayTracer moved(scene, glm::dvec3(0.0, 6.0, 8.0));
        QCOMPARE(moved.movingCasterCount(), 4);
        scene.poseAt(2.1);
        moved.pose(scene);
        const RayTracer fresh(scene, glm::dvec3(0.0, 6.0, 8.0));
        const glm::dvec3 toLight = glm::normalize(glm::dvec3(-4.0, 8.0, 3.0));
        int hits = 0;
        for (int i = 0; i < 120; ++i) {
            for (int j = 0; j < 120; ++j) {
                const glm::dvec3 from(-4.0 + 8.0 * i / 119.0, 0.0, -4.0 + 8.0 * j / 119.0);
                const bool a = moved.occluded(from, toLight, 100.0), b = fresh.occluded(from, toLight, 100.0);
                QCOMPARE(a, b);
                hits += a;
            }
        }
        QVERIFY(hits > 500);
    }

private:
    QTemporaryDir m_dir;
    QString m_moving;
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestAnimation)
#include "tst_Animation.moc"
