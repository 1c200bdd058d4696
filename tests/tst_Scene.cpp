// Meshes and presets without GL: closed meshes wind outward, normals agree with the winding,
// and the presets put things where the tutorial scene has them.
#include "ProceduralTexture.h"
#include "SceneFileError.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsKeys.h"

#include <glm/glm.hpp>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace shadowlab;

Q_DECLARE_METATYPE(shadowlab::Mesh)

namespace {

// A scene file of `shapes` (JSON text of the list) and `more` keys, written to `dir`.
QString writeSceneFile(const QTemporaryDir& dir, const QString& name, const QByteArray& shapes, const QByteArray& more = {})
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("{ \"shapes\": " + shapes + (more.isEmpty() ? QByteArray() : ", " + more) + " }");
    return path;
}

bool near(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; }

} // namespace

class TestScene : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void meshesWindOutward_data()
    {
        QTest::addColumn<Mesh>("mesh");
        QTest::newRow("plane") << meshes::plane(2.0f, 1.0f);
        QTest::newRow("cube") << meshes::cube();
        QTest::newRow("sphere") << meshes::sphere(24, 12);
        QTest::newRow("torus") << meshes::torus(1.0f, 0.3f, 32, 16);
        QTest::newRow("pyramid") << meshes::pyramid();
    }

    void meshesWindOutward()
    {
        QFETCH(Mesh, mesh);
        QVERIFY(!mesh.indices.empty());
        QCOMPARE(mesh.indices.size() % 3, std::size_t(0));
        for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
            const Vertex& a = mesh.vertices.at(mesh.indices[i]);
            const Vertex& b = mesh.vertices.at(mesh.indices[i + 1]);
            const Vertex& c = mesh.vertices.at(mesh.indices[i + 2]);
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            if (glm::length(face) < 1e-7f)
                continue; // pole slivers of the sphere
            const glm::vec3 average = a.normal + b.normal + c.normal;
            QVERIFY2(glm::dot(face, average) > 0.0f, qPrintable(QString("triangle %1 winds against its normals").arg(i / 3)));
            QCOMPARE_LT(std::abs(glm::length(a.normal) - 1.0f), 1e-4f);
        }
    }

    // Smooth-shaded meshes are told from flat-shaded ones by their normals, whichever way the
    // normals face against the winding.
    void smoothShadingIsFoundFromTheNormals()
    {
        QVERIFY(smoothShaded(meshes::sphere(24, 12)));
        QVERIFY(smoothShaded(meshes::torus(1.0f, 0.3f, 32, 16)));
        QVERIFY(!smoothShaded(meshes::cube()));
        QVERIFY(!smoothShaded(meshes::plane(2.0f, 1.0f)));
        QVERIFY(!smoothShaded(meshes::pyramid()));
        Mesh inward = meshes::cube();
        for (Vertex& v : inward.vertices)
            v.normal = -v.normal;
        QVERIFY(!smoothShaded(inward));
        // One vertex of a cube bent by a tenth of a degree is enough; a hundredth is rounding.
        for (const auto& [degrees, smooth] : {std::pair{0.1, true}, std::pair{0.01, false}}) {
            Mesh bent = meshes::cube();
            const double a = glm::radians(degrees);
            const glm::vec3 n = bent.vertices[0].normal;
            const glm::vec3 side = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
            bent.vertices[0].normal = glm::normalize(float(std::cos(a)) * n + float(std::sin(a)) * glm::normalize(glm::cross(n, side)));
            QCOMPARE(smoothShaded(bent), smooth);
        }
    }

    void seedSceneMatchesTheTutorial()
    {
        const Scene s = buildScene("seed");
        QCOMPARE(s.objects.size(), std::size_t(4));
        const Bounds ground = s.worldBounds(s.objects[0]);
        QCOMPARE(ground.min.y, -0.5);
        QCOMPARE(ground.max.x - ground.min.x, 50.0);
        const Bounds high = s.worldBounds(s.objects[1]);
        QVERIFY(high.center() == glm::dvec3(0.0, 1.5, 0.0));
        QCOMPARE(high.max.x - high.min.x, 1.0);
        const Bounds resting = s.worldBounds(s.objects[2]);
        QCOMPARE(resting.min.y, -0.5); // rests on the plane
        QVERIFY(glm::length(s.worldBounds(s.objects[3]).center() - glm::dvec3(-1.0, 0.0, 2.0)) < 1e-12);
        QVERIFY(!s.casterBounds().isEmpty());
    }

    void everyPresetBuilds()
    {
        for (const QString& name : sceneNames()) {
            const Scene s = buildScene(name);
            QCOMPARE(s.name, name);
            QVERIFY(s.objects.size() >= 2);
            QVERIFY(!s.bounds().isEmpty());
        }
        QCOMPARE(buildScene("cubes").objects.size(), std::size_t(11));
    }

    // Every preset is one resource file: what it is, its shapes or generator, and settings that
    // hold.
    void everyPresetIsAFile()
    {
        QVERIFY(sceneNames().size() >= 7);
        QCOMPARE(sceneNames().front(), QStringLiteral("seed"));
        for (const QString& name : sceneNames()) {
            QFile file(QStringLiteral("%1/%2.json").arg(QLatin1String(kScenePresetFolder), name));
            QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(name));
            const QJsonObject preset = QJsonDocument::fromJson(file.readAll()).object();
            QVERIFY2(preset.value(QStringLiteral("about")).toString().size() > 20, qPrintable(name));
            QVERIFY2(preset.value(QStringLiteral("shapes")).isArray() != preset.value(QStringLiteral("generator")).isString(), qPrintable(name));
            const Settings s = presetSettings(name);
            QCOMPARE(s.scene, name);
            ensureValid(s);
            // The camera looks at the scene from outside it.
            const Bounds b = buildScene(name).modelBounds();
            const bool inside = glm::all(glm::greaterThanEqual(s.camera.position, b.min)) && glm::all(glm::lessThanEqual(s.camera.position, b.max));
            QVERIFY2(!inside || name == u"city", qPrintable(name));
        }
        QCOMPARE(presetSettings(QStringLiteral("city:500")).camera.position, presetSettings(QStringLiteral("city")).camera.position);
    }

    // Each shape is where, as large and as turned as its file says, and equal shapes share a mesh.
    void shapesAreWhereTheFileSays()
    {
        QTemporaryDir dir;
        const QString path = writeSceneFile(dir, QStringLiteral("shapes.json"), R"([
            { "shape": "cube", "name": "a", "position": [1, 2, 3], "scale": 0.5 },
            { "shape": "cube", "name": "long", "position": [0, 1, 0], "rotation": [0, 90, 0], "scale": [2, 1, 1], "casts": false },
            { "shape": "cube", "name": "tilted", "rotation": { "angle": 45, "axis": [0, 0, 2] }, "texture": "flat", "colour": [0.2, 0.4, 0.6] },
            { "shape": "sphere", "segments": 12, "rings": 6, "position": [-3, 1, 0] },
            { "shape": "torus", "major": 1, "minor": 0.25, "position": [3, 1, 0] },
            { "shape": "pyramid", "receives": false },
            { "shape": "card", "texture": "checker" }
        ])", R"("camera.position": [9, 8, 7])");
        const std::shared_ptr<const Scene> scene = loadSceneFile(path);
        QCOMPARE(scene->objects.size(), std::size_t(8));     // and the ground laid under them
        QCOMPARE(scene->objects.back().name, QStringLiteral("ground"));
        const Bounds a = scene->worldBounds(scene->objects[0]);
        QVERIFY(near(a.min, {0.5, 1.5, 2.5}) && near(a.max, {1.5, 2.5, 3.5}));
        const Bounds longCube = scene->worldBounds(scene->objects[1]);
        QVERIFY(near(longCube.max - longCube.min, {2.0, 2.0, 4.0}));    // 90 degrees about y: x becomes z
        QVERIFY(!scene->objects[1].castsShadow && scene->objects[1].receivesShadow);
        const Bounds tilted = scene->worldBounds(scene->objects[2]);
        QVERIFY(std::abs((tilted.max.x - tilted.min.x) - 2.0 * std::sqrt(2.0)) < 1e-9);     // 45 degrees about z
        QCOMPARE(scene->objects[2].texture, TextureKind::Flat);
        QVERIFY(glm::length(scene->objects[2].baseColour - glm::vec3(0.2f, 0.4f, 0.6f)) < 1e-6f);
        QCOMPARE(scene->objects[3].name, QStringLiteral("sphere 4"));
        QCOMPARE(scene->objects[0].mesh, scene->objects[1].mesh);
        QVERIFY(!scene->objects[5].receivesShadow);
        QCOMPARE(scene->objects[6].texture, TextureKind::Checker);
        QCOMPARE(scene->meshes.size(), std::size_t(6));       // cube, sphere, torus, pyramid, card, ground
        QCOMPARE(*scene->groundHeight, scene->bounds().min.y);
        QCOMPARE(sceneFileSettings(path).camera.position, glm::dvec3(9.0, 8.0, 7.0));
        QVERIFY2(!sceneFileSettings(path).bias.cullFront, "a casting card is open: front faces must not be culled");
    }

    // A ground shape is the ground: none is added, and the camera stays above it.
    void aGroundShapeIsTheGround()
    {
        QTemporaryDir dir;
        const QString path = writeSceneFile(dir, QStringLiteral("ground.json"),
                                            R"([{ "shape": "ground", "height": -2, "size": 10 }, { "shape": "cube" }])");
        const std::shared_ptr<const Scene> scene = loadSceneFile(path);
        QCOMPARE(scene->objects.size(), std::size_t(2));
        QCOMPARE(*scene->groundHeight, -2.0);
        QCOMPARE(scene->bounds().min.x, -10.0);
        QCOMPARE(scene->objects.front().texture, TextureKind::Checker);
        QVERIFY2(sceneFileSettings(path).bias.cullFront, "closed shapes keep front-face culling");
    }

    void badShapesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("shapes");
        QTest::addColumn<QString>("message");
        QTest::newRow("no shapes or models") << QByteArray("[]") << QStringLiteral("lists no models and no shapes");
        QTest::newRow("not a list") << QByteArray(R"({"shape": "cube"})") << QStringLiteral("\"shapes\" must be a list");
        QTest::newRow("not an object") << QByteArray(R"(["cube"])") << QStringLiteral("shapes[0] must be an object");
        QTest::newRow("misspelt shape") << QByteArray(R"([{"shape": "cubee"}])") << QStringLiteral("did you mean 'cube'");
        QTest::newRow("no shape") << QByteArray(R"([{"position": [0, 0, 0]}])") << QStringLiteral("needs a \"shape\", one of cube, pyramid");
        QTest::newRow("misspelt key") << QByteArray(R"([{"shape": "cube", "positon": [0, 0, 0]}])") << QStringLiteral("did you mean 'position'");
        QTest::newRow("two coordinates") << QByteArray(R"([{"shape": "cube", "position": [1, 2]}])") << QStringLiteral("\"position\" must be three numbers");
        QTest::newRow("text coordinate") << QByteArray(R"([{"shape": "cube", "position": [1, "2", 3]}])") << QStringLiteral("must be three numbers");
        QTest::newRow("far away") << QByteArray(R"([{"shape": "cube", "position": [1e9, 0, 0]}])") << QStringLiteral("must be three numbers in");
        QTest::newRow("zero scale") << QByteArray(R"([{"shape": "cube", "scale": 0}])") << QStringLiteral("\"scale\" must be positive");
        QTest::newRow("mirroring scale") << QByteArray(R"([{"shape": "cube", "scale": [-1, 1, 1]}])") << QStringLiteral("\"scale\" must be");
        QTest::newRow("zero axis") << QByteArray(R"([{"shape": "cube", "rotation": {"angle": 10, "axis": [0, 0, 0]}}])") << QStringLiteral("\"axis\" must not be zero");
        QTest::newRow("torus inside out") << QByteArray(R"([{"shape": "torus", "major": 0.2, "minor": 0.5}])") << QStringLiteral("\"minor\" radius must be smaller");
        QTest::newRow("torus of two segments") << QByteArray(R"([{"shape": "torus", "segments": 2}])") << QStringLiteral("\"segments\" must be a whole number in [3, 1024]");
        QTest::newRow("fractional sides") << QByteArray(R"([{"shape": "torus", "sides": 7.5}])") << QStringLiteral("\"sides\" must be a whole number");
        QTest::newRow("plane of no size") << QByteArray(R"([{"shape": "plane", "size": 0}])") << QStringLiteral("\"size\" must be a number");
        QTest::newRow("unknown texture") << QByteArray(R"([{"shape": "cube", "texture": "marble"}])") << QStringLiteral("'marble' is not one of wood, checker, flat");
        QTest::newRow("bright colour") << QByteArray(R"([{"shape": "cube", "colour": [2, 0, 0]}])") << QStringLiteral("\"colour\" must be three numbers in [0, 1]");
        QTest::newRow("misspelt rotation") << QByteArray(R"([{"shape": "cube", "rotation": {"angel": 10}}])") << QStringLiteral("did you mean 'angle'");
        QTest::newRow("a placed ground") << QByteArray(R"([{"shape": "ground", "position": [0, 1, 0]}])") << QStringLiteral("unknown key \"position\"; a ground takes");
        QTest::newRow("a cube's divisions") << QByteArray(R"([{"shape": "cube", "segments": 8}])") << QStringLiteral("unknown key \"segments\"; a cube takes");
        QTest::newRow("vanishing scale") << QByteArray(R"([{"shape": "cube", "scale": 1e-300}])") << QStringLiteral("\"scale\" must be positive, at least");
        QTest::newRow("beyond float's reach") << QByteArray(R"([{"shape": "cube", "position": [1e7, 0, 0], "scale": 10}])") << QStringLiteral("reaches beyond");
        QTest::newRow("too many triangles") << QByteArray(R"([{"shape": "sphere", "segments": 1024, "rings": 1024}, {"shape": "sphere", "segments": 1024, "rings": 1024},
            {"shape": "sphere", "segments": 1024, "rings": 1024}, {"shape": "sphere", "segments": 1024, "rings": 1024}, {"shape": "sphere", "segments": 1024, "rings": 1024}])")
                                            << QStringLiteral("shapes[4]: the shapes so far have");
        QTest::newRow("casts as text") << QByteArray(R"([{"shape": "cube", "casts": "yes"}])") << QStringLiteral("\"casts\" must be true or false");
    }
    void badShapesAreRefused()
    {
        QFETCH(QByteArray, shapes);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = writeSceneFile(dir, QStringLiteral("bad.json"), shapes);
        try {
            loadSceneFile(path);
            QFAIL("the file was accepted");
        } catch (const SceneFileError& e) {
            const QString what = QString::fromUtf8(e.what());
            QVERIFY2(what.contains(message), qPrintable(what));
            QVERIFY2(what.contains(QStringLiteral("bad.json")), qPrintable(what));
        }
    }

    void texturesAreGeneratedNotFlat()
    {
        for (TextureKind kind : {TextureKind::Checker, TextureKind::Wood}) {
            const QImage image = makeProceduralTexture(kind, 64);
            QCOMPARE(image.size(), QSize(64, 64));
            QSet<QRgb> colours;
            for (int y = 0; y < 64; y += 4)
                for (int x = 0; x < 64; x += 4)
                    colours.insert(image.pixel(x, y));
            QVERIFY(colours.size() > 1);
        }
    }
};

QTEST_APPLESS_MAIN(TestScene)
#include "tst_Scene.moc"
