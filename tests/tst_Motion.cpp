// Motion without GL: each kind of motion places an object where its definition says at every
// instant, a sweep holds every pose, scene files give shapes motions (and refuse bad ones with
// the shape and key named), and the city's traffic moves.
#include "Motion.h"
#include "SceneFileError.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <random>

using namespace shadowlab;

namespace {

QString writeSceneFile(const QTemporaryDir& dir, const QString& name, const QByteArray& shapes)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("{ \"shapes\": " + shapes + " }");
    return path;
}

glm::dvec3 placed(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }
bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-9) { return glm::length(a - b) < tolerance; }
bool inside(const Bounds& b, const glm::dvec3& p)
{
    return glm::all(glm::greaterThanEqual(p, b.min - 1e-9)) && glm::all(glm::lessThanEqual(p, b.max + 1e-9));
}

Motion turning(Motion::Kind kind)
{
    Motion m;
    m.kind = kind;
    m.point = {1.0, 0.0, 0.0};
    m.axis = {0.0, 1.0, 0.0};
    m.period = 4.0;
    m.amplitude = kind == Motion::Kind::Bob ? 0.5 : glm::radians(30.0);
    m.post = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, 1.0, 0.0));
    return m;
}

Motion path(bool smooth)
{
    Motion m;
    m.kind = Motion::Kind::Path;
    m.keys = {{0.0, {0, 0, 0}, glm::dquat(1, 0, 0, 0)}, {1.0, {2, 0, 0}, glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 1, 0))},
              {3.0, {2, 0, 4}, glm::angleAxis(glm::pi<double>(), glm::dvec3(0, 1, 0))}};
    m.period = 3.0;
    m.smooth = smooth;
    return m;
}

} // namespace

class TestMotion : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void turnsAndBobsAsDefined()
    {
        // A spin turns the object's point about the axis: a quarter period is a quarter turn
        // (counter-clockwise seen from +y: +x goes to -z), a whole one comes back.
        const Motion spin = turning(Motion::Kind::Spin);
        const glm::dvec3 origin(0.0);   // post puts it at (3, 1, 0): 2 from the axis through (1, 0, 0)
        QVERIFY(near(placed(spin.at(0.0), origin), {3, 1, 0}));
        QVERIFY(near(placed(spin.at(1.0), origin), {1, 1, -2}));
        QVERIFY(near(placed(spin.at(4.0), origin), {3, 1, 0}));
        QVERIFY(near(placed(spin.at(-3.0), origin), placed(spin.at(1.0), origin)));
        // A swing goes its amplitude either way and back.
        const Motion swing = turning(Motion::Kind::Swing);
        const glm::dvec3 widest = placed(swing.at(1.0), origin) - glm::dvec3(1, 1, 0);
        QCOMPARE(std::round(glm::degrees(std::atan2(-widest.z, widest.x)) * 1e6) / 1e6, 30.0);
        QVERIFY(near(placed(swing.at(2.0), origin), {3, 1, 0}));
        QVERIFY(near(placed(swing.at(3.0), origin) - glm::dvec3(1, 1, 0), widest * glm::dvec3(1, 1, -1)));
        // A bob moves along its axis by its amplitude.
        const Motion bob = turning(Motion::Kind::Bob);
        QVERIFY(near(placed(bob.at(1.0), origin), {3, 1.5, 0}));
        QVERIFY(near(placed(bob.at(3.0), origin), {3, 0.5, 0}));
        // A start offset is a shift of the clock.
        Motion late = spin;
        late.start = 1.0;
        QVERIFY(near(placed(late.at(0.0), origin), placed(spin.at(1.0), origin)));
    }

    void pathsPassThroughTheirKeys()
    {
        for (const bool smooth : {false, true}) {
            const Motion m = path(smooth);
            for (const MotionKey& key : m.keys) {
                const glm::dmat4 at = m.at(key.time == m.period ? key.time - 1e-12 : key.time);
                QVERIFY2(near(placed(at, {0, 0, 0}), key.position, 1e-6), smooth ? "smooth" : "linear");
            }
            // Linear halfway between keys is the middle; smooth bends toward the next key but stays near.
            const glm::dvec3 half = placed(m.at(0.5), {0, 0, 0});
            if (!smooth)
                QVERIFY(near(half, {1, 0, 0}));
            else
                QVERIFY(glm::length(half - glm::dvec3(1, 0, 0)) < 0.5);
            // The rotation turns halfway too: a point at +x has turned 45°.
            const glm::dvec3 turned = placed(m.at(0.5), {1, 0, 0}) - half;
            QVERIFY(near(turned, glm::dvec3(std::cos(glm::quarter_pi<double>()), 0, -std::sin(glm::quarter_pi<double>())), 1e-9));
            // After the last key it starts again.
            QVERIFY(near(placed(m.at(3.5), {0, 0, 0}), placed(m.at(0.5), {0, 0, 0})));
        }
    }

    void aSweepHoldsEveryPose_data()
    {
        QTest::addColumn<int>("kind");
        for (int k = 0; k <= int(Motion::Kind::Path); ++k)
            QTest::newRow(qPrintable(QString::number(k))) << k;
    }
    void aSweepHoldsEveryPose()
    {
        QFETCH(int, kind);
        const Motion m = kind == int(Motion::Kind::Path) ? path(true) : turning(Motion::Kind(kind));
        Bounds local;
        local.extend(glm::dvec3(-0.5, -0.2, -1.0));
        local.extend(glm::dvec3(0.5, 0.2, 1.0));
        const Bounds swept = m.sweptBounds(local);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> time(-10.0, 10.0);
        for (int i = 0; i < 2000; ++i) {
            const glm::dmat4 at = m.at(time(random));
            for (const glm::dvec3& c : local.corners())
                QVERIFY(inside(swept, placed(at, c)));
        }
        // Not much more than the poses: within the largest step of a sample.
        QVERIFY(glm::length(swept.max - swept.min) < 20.0);
    }

    void badMotionsAreNamed()
    {
        Motion m = path(false);
        QVERIFY(motionProblem(m).isEmpty());
        m.keys[2].time = 1.0;
        QVERIFY(motionProblem(m).contains(QStringLiteral("after key 1")));
        m = turning(Motion::Kind::Spin);
        m.period = 0.0;
        QVERIFY(motionProblem(m).contains(QStringLiteral("period")));
        m = turning(Motion::Kind::Spin);
        m.axis = glm::dvec3(NAN);
        QVERIFY(!motionProblem(m).isEmpty());
    }

    void shapesMoveAsTheirFileSays()
    {
        QTemporaryDir dir;
        const QString file = writeSceneFile(dir, QStringLiteral("moving.json"), R"([
            { "shape": "ground", "height": 0 },
            { "name": "still", "shape": "cube", "position": [4, 1, 0] },
            { "name": "spinner", "shape": "cube", "position": [0, 1, 0], "scale": [2, 0.1, 0.1], "motion": { "type": "spin", "period": 4 } },
            { "name": "orbiter", "shape": "sphere", "position": [2, 1, 0], "scale": 0.3, "motion": { "type": "orbit", "centre": [0, 0, 0], "speed": -90 } },
            { "name": "bobber", "shape": "cube", "position": [0, 3, 0], "scale": 0.2, "motion": { "type": "bob", "amplitude": 1, "period": 4 } },
            { "name": "driver", "shape": "cube", "position": [-3, 0.5, 0], "scale": 0.5, "motion": { "type": "path", "keys": [
                { "time": 0 }, { "time": 2, "position": [-3, 0.5, 4], "rotation": { "angle": 90, "axis": [0, 1, 0] } } ] } }
        ])");
        Scene scene = *loadSceneFile(file);
        QCOMPARE(scene.objects.size(), std::size_t(6));
        QVERIFY(scene.moves());
        QCOMPARE(scene.clipLength(), 4.0);
        QVERIFY(!scene.objects[1].motion);
        const std::vector<glm::dmat4> rest = [&] {
            std::vector<glm::dmat4> m;
            for (const SceneObject& o : scene.objects)
                m.push_back(o.model);
            return m;
        }();
        const std::vector<std::size_t> moved = scene.poseAt(1.0);
        QCOMPARE(moved, (std::vector<std::size_t>{2, 3, 4, 5}));
        // The spinner's long side turned from x to z; the orbiter, clockwise at 90°/s, went from
        // +x to +z; the bobber is up by its amplitude; the driver is halfway down its path, turned.
        QVERIFY(near(placed(scene.objects[2].model, {1, 0, 0}), {0, 1, -2}));
        QVERIFY(near(placed(scene.objects[3].model, {0, 0, 0}), {0, 1, 2}));
        QVERIFY(near(placed(scene.objects[4].model, {0, 0, 0}), {0, 4, 0}));
        QVERIFY(near(placed(scene.objects[5].model, {0, 0, 0}), {-3, 0.5, 2}));
        QVERIFY(near(placed(scene.objects[5].model, {1, 0, 0}) - glm::dvec3(-3, 0.5, 2), glm::dvec3(std::cos(glm::quarter_pi<double>()), 0, -std::sin(glm::quarter_pi<double>())) * 0.5));
        QCOMPARE(scene.objects[1].model, rest[1]);
        // Time 0 is where the file puts them; the scene's bounds hold the whole clip.
        scene.poseAt(0.0);
        for (std::size_t i = 0; i < rest.size(); ++i)
            QVERIFY(glm::length(glm::dvec3(scene.objects[i].model[3] - rest[i][3])) < 1e-9);
        QVERIFY(scene.bounds().max.y >= 4.0 - 1e-9 && scene.bounds().max.z >= 4.0 - 1e-9);
        QVERIFY(sceneMoves(file));
    }

    void badMotionsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("motion");
        QTest::addColumn<QString>("message");
        QTest::newRow("not an object") << QByteArray(R"("spin")") << QStringLiteral("\"motion\" must be an object");
        QTest::newRow("no type") << QByteArray(R"({"period": 2})") << QStringLiteral("shapes[0].motion: needs a \"type\", one of spin, orbit, swing, bob, path");
        QTest::newRow("misspelt type") << QByteArray(R"({"type": "spinn"})") << QStringLiteral("did you mean 'spin'");
        QTest::newRow("zero period") << QByteArray(R"({"type": "spin", "period": 0})") << QStringLiteral("\"period\" must be a number in");
        QTest::newRow("period and speed") << QByteArray(R"({"type": "orbit", "period": 2, "speed": 30})") << QStringLiteral("not both");
        QTest::newRow("still speed") << QByteArray(R"({"type": "spin", "speed": 0})") << QStringLiteral("leave \"motion\" out");
        QTest::newRow("zero axis") << QByteArray(R"({"type": "spin", "axis": [0, 0, 0]})") << QStringLiteral("\"axis\" must not be zero");
        QTest::newRow("a bob's centre") << QByteArray(R"({"type": "bob", "centre": [0, 0, 0]})") << QStringLiteral("unknown key \"centre\"; a bob motion takes");
        QTest::newRow("wide swing") << QByteArray(R"({"type": "swing", "angle": 270})") << QStringLiteral("\"angle\" must be a number in [0, 180]");
        QTest::newRow("one key") << QByteArray(R"({"type": "path", "keys": [{"time": 0}]})") << QStringLiteral("at least two");
        QTest::newRow("late first key") << QByteArray(R"({"type": "path", "keys": [{"time": 1}, {"time": 2}]})") << QStringLiteral("keys[0]: the first key's \"time\" must be 0");
        QTest::newRow("keys out of order") << QByteArray(R"({"type": "path", "keys": [{"time": 0}, {"time": 2}, {"time": 1}]})") << QStringLiteral("shapes[0].motion.keys[2]: \"time\" must be after");
        QTest::newRow("key without time") << QByteArray(R"({"type": "path", "keys": [{"time": 0}, {"position": [1, 0, 0]}]})") << QStringLiteral("needs a \"time\"");
        QTest::newRow("key's position") << QByteArray(R"({"type": "path", "keys": [{"time": 0}, {"time": 1, "position": [1, 0]}]})") << QStringLiteral("\"position\" must be three numbers");
        QTest::newRow("a path's period") << QByteArray(R"({"type": "path", "period": 3, "keys": [{"time": 0}, {"time": 1}]})") << QStringLiteral("unknown key \"period\"; a path motion takes");
    }
    void badMotionsAreRefused()
    {
        QFETCH(QByteArray, motion);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString file = writeSceneFile(dir, QStringLiteral("bad-motion.json"), R"([{ "shape": "cube", "motion": )" + motion + "}]");
        try {
            loadSceneFile(file);
            QFAIL("the file was accepted");
        } catch (const SceneFileError& e) {
            const QString what = QString::fromUtf8(e.what());
            QVERIFY2(what.contains(message), qPrintable(what));
            QVERIFY2(what.contains(QStringLiteral("bad-motion.json")), qPrintable(what));
        }
    }

    void theCityHasTraffic()
    {
        QCOMPARE(cityVehicleCount(QStringLiteral("city")), 0);
        QCOMPARE(cityVehicleCount(QStringLiteral("city+50")), 50);
        QCOMPARE(cityBuildingCount(QStringLiteral("city+50")), kCityBuildings);
        QCOMPARE(cityBuildingCount(QStringLiteral("city:300+10")), 300);
        QCOMPARE(cityVehicleCount(QStringLiteral("city:300+10")), 10);
        QCOMPARE(cityBuildingCount(QStringLiteral("city+x")), -1);
        QCOMPARE(cityBuildingCount(QStringLiteral("city+99999")), -1);
        Settings s;
        try {
            applySetting(s, QStringLiteral("scene"), QStringLiteral("city+-3"));
            QFAIL("a negative traffic was accepted");
        } catch (const SettingsError& e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("city+50")), e.what());
        }
        Scene still = buildScene(QStringLiteral("city:300"));
        Scene busy = buildScene(QStringLiteral("city:300+10"));
        QVERIFY(!still.moves());
        QCOMPARE(busy.objects.size(), still.objects.size() + 10);
        QVERIFY(busy.moves());
        // Every vehicle drives along a street at ground level and comes back: at any instant it
        // stands on the ground, inside the city, and it is somewhere else a few seconds later.
        const std::vector<std::size_t> moved = busy.poseAt(3.0);
        QCOMPARE(moved.size(), std::size_t(10));
        for (std::size_t i : moved) {
            const Bounds b = Bounds{glm::dvec3(-1.0), glm::dvec3(1.0)}.transformed(busy.objects[i].model);
            QVERIFY(std::abs(b.min.y) < 1e-9);
            QVERIFY(std::abs(b.center().x) < 600.0 && std::abs(b.center().z) < 600.0);
        }
        const glm::dvec3 before(busy.objects[moved.front()].model[3]);
        busy.poseAt(6.0);
        QVERIFY(glm::length(glm::dvec3(busy.objects[moved.front()].model[3]) - before) > 10.0);
        QVERIFY(sceneMoves(QStringLiteral("city:300+10")) && !sceneMoves(QStringLiteral("city:300")));
    }
};

QTEST_GUILESS_MAIN(TestMotion)
#include "tst_Motion.moc"
