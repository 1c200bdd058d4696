// Your own scenes: models from Debian's assimp-testmodels load with the right triangle counts
// and sizes in every format, their shadows agree with the Embree reference, broken files give
// an error that names the file and the problem, a scene file places models and sets keys,
// references are cached by content, and the window keeps its scene when a file is bad.
#include "AccuracyDock.h"
#include "Application.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "ReferenceAgreement.h"
#include "MainWindow.h"
#include "ModelImporter.h"
#include "LightMath.h"
#include "SliderSpinBox.h"
#include "PropertiesDock.h"
#include "RayTracer.h"
#include "RenderError.h"
#include "ReportSweep.h"
#include "Renderer.h"
#include "SceneFileError.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SceneView.h"
#include "SettingsKeys.h"
#include "ShadowReference.h"
#include "TestFiles.h"
#include "TestPictures.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QUndoStack>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QMimeData>
#include <QTemporaryDir>
#include <QToolButton>
#include <QMenu>
#include <QtTest>

#include <algorithm>
#include <initializer_list>
#include <memory>

using namespace shadowlab;

namespace {

const QString kModels = kTestModels;

QString model(const QString& relative)
{
    return kModels + relative;
}

// Whether side A of `window` has drawn the scene `name` (a file opens in the background).
bool drawsScene(const MainWindow& window, const QString& name)
{
    const Renderer* renderer = window.sceneView(MainWindow::Side::A)->renderer();
    return renderer && renderer->scene() && renderer->scene()->name == name;
}

// A shown explorer window at its default size, with no session read or written.
std::unique_ptr<MainWindow> shownWindow()
{
    auto window = std::make_unique<MainWindow>(MainWindow::Persistence::None);
    window->resize(1200, 750);
    window->show();
    return window;
}

std::size_t triangleCount(const Scene& scene, bool withGround = false)
{
    std::size_t n = 0;
    for (const SceneObject& o : scene.objects) {
        if (withGround || o.texture != TextureKind::Checker)
            n += scene.meshes.at(std::size_t(o.mesh)).indices.size() / 3;
    }
    return n;
}

QByteArray readFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return file.readAll();
}

// A two-triangle square of side `size` at height `size`, and a small triangle on y = 0 beside
// it where the ground will go, as OBJ text.
QByteArray squareObj(double size)
{
    return QStringLiteral("v 0 %1 0\nv %1 %1 0\nv %1 %1 %1\nv 0 %1 %1\nv %2 0 %2\nv %3 0 %2\nv %2 0 %3\nf 1 3 2\nf 1 4 3\nf 5 7 6\n")
        .arg(size, 0, 'g', 17)
        .arg(3.0 * size, 0, 'g', 17)
        .arg(3.1 * size, 0, 'g', 17)
        .toUtf8();
}

// The largest difference between two placements' entries.
double difference(const glm::dmat4& a, const glm::dmat4& b)
{
    double largest = 0.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            largest = std::max(largest, std::abs(a[c][r] - b[c][r]));
    }
    return largest;
}

// A glTF 2 with one triangle on node "box", a child of node "arm": in the first animation,
// "Wave", the arm turns 90° about y from 1 s to 3 s while the box slides from (2, 0, 0) to
// (2, 1, 0) from 0 s to 2 s; a second animation, "Idle", follows. Every length times `unit`;
// the arm is scaled by `armScaleX` along its x (not keyed: Assimp 5.2 fills a mirrored node's
// missing rotation key with a turn that undoes its mirror, so the box's own scale is left alone).
QByteArray armGltf(double unit, double armScaleX)
{
    QByteArray buffer;
    const auto floats = [&buffer](std::initializer_list<double> values) {
        for (const double v : values) {
            const float f = float(v);
            buffer.append(reinterpret_cast<const char*>(&f), sizeof f);
        }
    };
    const double u = unit, half = std::sqrt(0.5);
    floats({0, 0, 0, u, 0, 0, 0, u, 0});            // at 0: the triangle
    floats({1, 3});                                 // at 36: the arm's key times
    floats({0, 0, 0, 1, 0, half, 0, half});         // at 44: its rotations (x, y, z, w)
    floats({0, 2});                                 // at 76: the box's key times
    floats({2 * u, 0, 0, 2 * u, u, 0});             // at 84: its translations
    const QString json = QStringLiteral(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "arm", "scale": [%5, 1, 1], "children": [1]}, {"name": "box", "translation": [%1, 0, 0], "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "buffers": [{"byteLength": %2, "uri": "data:application/octet-stream;base64,%3"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                        {"buffer": 0, "byteOffset": 44, "byteLength": 32}, {"buffer": 0, "byteOffset": 76, "byteLength": 8},
                        {"buffer": 0, "byteOffset": 84, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [%4, %4, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [1], "max": [3]},
                      {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC4"},
                      {"bufferView": 3, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [2]},
                      {"bufferView": 4, "componentType": 5126, "count": 2, "type": "VEC3"}],
        "animations": [{"name": "Wave", "samplers": [{"input": 1, "output": 2}, {"input": 3, "output": 4}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "translation"}}]},
                       {"name": "Idle", "samplers": [{"input": 3, "output": 4}],
                        "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}]})")
                             .arg(2 * u, 0, 'g', 17)
                             .arg(buffer.size())
                             .arg(QString::fromLatin1(buffer.toBase64()))
                             .arg(u, 0, 'g', 17)
                             .arg(armScaleX, 0, 'g', 17);
    return json.toUtf8();
}

// Where armGltf()'s box is at `t` seconds, worked out by hand: the arm's turn times the box's
// slide, each held before its first key and after its last.
glm::dmat4 armBoxAt(double t, double unit, double armScaleX)
{
    const double turn = glm::radians(90.0) * std::clamp((t - 1.0) / 2.0, 0.0, 1.0);
    const double rise = unit * std::clamp(t / 2.0, 0.0, 1.0);
    return glm::rotate(glm::dmat4(1.0), turn, glm::dvec3(0.0, 1.0, 0.0)) * glm::scale(glm::dmat4(1.0), glm::dvec3(armScaleX, 1.0, 1.0))
           * glm::translate(glm::dmat4(1.0), glm::dvec3(2.0 * unit, rise, 0.0));
}

using probe::Agreement;
using probe::agreement;

} // namespace

class TestModelImport : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase()
    {
        if (!QFileInfo::exists(model(QStringLiteral("OBJ/box.obj"))))
            QSKIP("assimp-testmodels is not installed; run scripts/setup.sh");
    }

    void formatsLoad_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("triangles");
        QTest::addColumn<double>("size");       // bounding-box diagonal in the file's units (0: not checked)
        QTest::addColumn<bool>("textured");     // a base-colour texture was loaded
        QTest::newRow("OBJ box") << model("OBJ/box.obj") << 12 << std::sqrt(3.0) << false;
        QTest::newRow("OBJ spider") << model("OBJ/spider.obj") << 0 << 0.0 << true;
        QTest::newRow("PLY cube") << model("PLY/cube.ply") << 12 << 0.0 << false;
        QTest::newRow("PLY Wuson") << model("PLY/Wuson.ply") << 0 << 0.0 << false;
        QTest::newRow("STL triangle") << model("STL/triangle.stl") << 1 << 0.0 << false;
        QTest::newRow("STL spider binary") << model("STL/Spider_binary.stl") << 0 << 0.0 << false;
        QTest::newRow("glTF 2 textured box") << model("glTF2/BoxTextured-glTF/BoxTextured.gltf") << 12 << std::sqrt(3.0) << true;
        QTest::newRow("glTF 2 binary engine") << model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb") << 0 << 0.0 << false;
        QTest::newRow("glTF 1 milk truck") << model("glTF/CesiumMilkTruck/CesiumMilkTruck.gltf") << 0 << 0.0 << true;
        QTest::newRow("COLLADA cube") << model("Collada/cube_triangulate.dae") << 12 << 0.0 << false;
        QTest::newRow("COLLADA duck, TGA texture") << model("Collada/duck.dae") << 0 << 0.0 << true;
        QTest::newRow("FBX box") << model("FBX/box.fbx") << 12 << 0.0 << false;
    }

    void formatsLoad()
    {
        QFETCH(QString, file);
        QFETCH(int, triangles);
        QFETCH(double, size);
        QFETCH(bool, textured);
        const Scene scene = importModel(file);
        const std::size_t count = triangleCount(scene);
        qInfo().noquote() << QFileInfo(file).fileName() << count << "triangles," << scene.objects.size() << "objects, size"
                          << glm::length(scene.bounds().max - scene.bounds().min) << scene.warnings;
        QVERIFY(count > 0);
        if (triangles > 0)
            QCOMPARE(int(count), triangles);
        const Bounds b = scene.bounds();
        QVERIFY(!b.isEmpty());
        QVERIFY(std::isfinite(glm::length(b.max - b.min)));
        if (size > 0.0)
            QVERIFY2(std::abs(glm::length(b.max - b.min) - size) < 1e-3 * size, qPrintable(QString::number(glm::length(b.max - b.min))));
        for (const Mesh& mesh : scene.meshes) {
            for (const Vertex& v : mesh.vertices) {
                QVERIFY(std::abs(glm::length(v.normal) - 1.0f) < 1e-3f);   // generated where missing, never NaN
                QVERIFY(std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
            }
        }
        const bool hasImage = std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.texture == TextureKind::Image; });
        QCOMPARE(hasImage, textured);
        QCOMPARE(scene.identity.size(), 64);    // sha256 in hex
    }

    // Textures in the formats real models use beside PNG and JPEG, read through Qt's
    // image-formats plugins (qt6-image-formats-plugins, installed by the set-up): TIFF and WebP
    // here, written by those plugins; TGA, which they only read, by the duck of formatsLoad().
    void texturesInPluginFormatsAreRead_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("TIFF") << "tif";
        QTest::newRow("WebP") << "webp";
    }
    void texturesInPluginFormatsAreRead()
    {
        QFETCH(QString, format);
        QTemporaryDir dir;
        QImage texture(8, 8, QImage::Format_RGB32);
        texture.fill(qRgb(200, 40, 40));
        QVERIFY2(texture.save(dir.filePath("red." + format), qPrintable(format.toUpper())), "Qt cannot write it: is qt6-image-formats-plugins installed?");
        writeFile(dir, "red.mtl", "newmtl red\nKd 1 1 1\nmap_Kd red." + format.toLatin1() + "\n");
        const QString path = writeFile(dir, "quad.obj", "mtllib red.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                                         "usemtl red\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
        const Scene scene = importModel(path);
        QVERIFY2(scene.warnings.filter("cannot be read").isEmpty(), qPrintable(scene.warnings.join('\n')));
        QVERIFY(std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.texture == TextureKind::Image; }));
    }

    // A frame builds no model: the file is handed in before it (supplyScene). Going back to the
    // file drawn now, after another was handed in (whose frame failed, say), reads nothing and
    // uploads nothing: the last good scene stays as it is.
    void aFileIsHandedInBeforeTheFrame()
    {
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const Settings box = presetSettings(model("OBJ/box.obj"));
        const Settings wuson = presetSettings(model("PLY/Wuson.ply"));
        const QSize size(64, 36);
        QVERIFY(renderer.needsSceneFile(box));
        m_headless->renderFrame(box, size);
        const Scene* drawn = renderer.scene();
        QVERIFY(drawn != nullptr);
        supplyScene(renderer, wuson);
        QVERIFY(!renderer.needsSceneFile(wuson));
        QVERIFY(!renderer.needsSceneFile(box));
        m_headless->renderFrame(box, size);
        QCOMPARE(renderer.scene(), drawn);
        // A file nobody handed in is refused by name, and the last frame's scene stays.
        Settings other = presetSettings(model("STL/Spider_ascii.stl"));
        QVERIFY(renderer.needsSceneFile(other));
        QVERIFY_THROWS_EXCEPTION(RenderError, renderer.render(other, RenderTarget{0, size}));
        QCOMPARE(renderer.scene(), drawn);
    }

    // What a user sees first: the model, a ground under it and a light that casts its shadow
    // onto the ground, and that shadow where the ray tracer puts it.
    void shadowsAgreeWithTheReference_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("filter");
        QTest::newRow("engine glb, hard") << model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb") << "hard";
        QTest::newRow("engine glb, default filter") << model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb") << "";
        QTest::newRow("milk truck glTF, hard") << model("glTF/CesiumMilkTruck/CesiumMilkTruck.gltf") << "hard";
        QTest::newRow("Wuson PLY, hard") << model("PLY/Wuson.ply") << "hard";
        QTest::newRow("spider STL, hard") << model("STL/Spider_binary.stl") << "hard";
        QTest::newRow("box OBJ, hard") << model("OBJ/box.obj") << "hard";
        QTest::newRow("COLLADA, hard") << model("Collada/cube_triangulate.dae") << "hard";
    }

    void shadowsAgreeWithTheReference()
    {
        QFETCH(QString, file);
        QFETCH(QString, filter);
        Settings s = presetSettings(file);
        if (!filter.isEmpty())
            applySetting(s, "filter.mode", filter);
        const Agreement a = agreement(m_headless->renderer(), s, QSize(240, 135));
        const QString numbers = QString("%1 counted, %2 shadowed in the reference, %3 false shadow, %4 false light")
                                    .arg(a.counted).arg(a.referenceShadowed).arg(a.falseShadow).arg(a.falseLight);
        qInfo().noquote() << numbers;
        QVERIFY2(a.counted > 2000, qPrintable(numbers));
        // The derived light casts a shadow that shows: some of the view is in shadow.
        QVERIFY2(a.referenceShadowed > 0.02 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseLight + a.falseShadow <= 0.02 * a.referenceShadowed + 0.004 * a.counted, qPrintable(numbers));
    }

    void brokenFilesGiveANamedError_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("problem");
        QTest::newRow("missing") << "/nonexistent/model.glb" << "no such file";
        QTest::newRow("unsupported") << model("invalid/readme.txt") << "not a model format";
        QTest::newRow("empty OBJ") << model("invalid/empty.obj") << "empty";
        QTest::newRow("empty PLY") << model("invalid/empty.ply") << "";
        QTest::newRow("points only PLY") << model("PLY/points.ply") << "no triangles";
        QTest::newRow("point cloud OBJ") << model("OBJ/point_cloud.obj") << "no triangles";
        QTest::newRow("glTF without its .bin") << model("glTF2/MissingBin/BoxTextured.gltf") << "cannot be read";
        QTest::newRow("glTF with infinite vertices") << model("glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb") << "";
        QTest::newRow("glTF indices out of range") << model("glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf") << "";
        QTest::newRow("glTF schema failure") << model("glTF2/SchemaFailures/sceneWrongType.gltf") << "";
        // A header that declares over a billion vertices in 309 bytes: refused at once, not
        // after minutes and gigabytes.
        QTest::newRow("lines only OBJ") << model("OBJ/testline.obj") << "only points or lines";
        QTest::newRow("glTF points primitive") << model("glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf") << "only points or lines";
        QTest::newRow("glTF 1 binary") << model("glTF/BoxTextured-glTF-Binary/BoxTextured.glb") << "glTF 2";
        QTest::newRow("OFF with an absurd vertex count") << model("invalid/OutOfMemory.off") << "header is damaged";
    }

    void brokenFilesGiveANamedError()
    {
        QFETCH(QString, file);
        QFETCH(QString, problem);
        try {
            Settings s;
            applySetting(s, "scene", file);
            const Scene scene = buildScene(s.scene);
            QFAIL(qPrintable(QString("loaded %1 triangles").arg(triangleCount(scene))));
        } catch (const SettingsError& e) {
            const QString message = QString::fromUtf8(e.what());
            qInfo().noquote() << message;
            QVERIFY2(message.contains(QFileInfo(file).fileName()), qPrintable(message));
            QVERIFY2(message.contains(problem), qPrintable(message));
            QCOMPARE(e.key(), QString("scene"));
        }
    }

    void truncatedFileGivesANamedError()
    {
        QTemporaryDir dir;
        const QByteArray bytes = readFile(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
        const QString path = writeFile(dir, "truncated.glb", bytes.left(bytes.size() / 2));
        QVERIFY_THROWS_EXCEPTION(SceneFileError, importModel(path));
        try {
            importModel(path);
        } catch (const SceneFileError& e) {
            QVERIFY(QString::fromUtf8(e.what()).contains("truncated.glb"));
            QVERIFY(QString::fromUtf8(e.what()).contains("export it again"));
        }
    }

    void absurdScalesAreNormalised_data()
    {
        QTest::addColumn<double>("size");
        QTest::addColumn<bool>("scaled");
        QTest::newRow("1e-6 units") << 1e-6 << true;
        QTest::newRow("1 unit") << 1.0 << false;
        QTest::newRow("1e6 units") << 1e6 << true;
    }

    void absurdScalesAreNormalised()
    {
        QFETCH(double, size);
        QFETCH(bool, scaled);
        QTemporaryDir dir;
        const QString path = writeFile(dir, "square.obj", squareObj(size));
        const Scene scene = importModel(path);
        const double diagonal = glm::length(scene.bounds().max - scene.bounds().min);
        QCOMPARE(int(triangleCount(scene)), 3);   // none merged away at either end of the range
        QVERIFY(std::isfinite(diagonal));
        QCOMPARE(scene.warnings.join(" ").contains("scaled by"), scaled);
        if (scaled)
            QVERIFY2(std::abs(diagonal - kNormalisedModelSize) < 1e-3 * kNormalisedModelSize, qPrintable(QString::number(diagonal)));
        // ... and it renders with a shadow the reference agrees with, not NaN.
        const Settings s = presetSettings(path);
        QVERIFY(validate(s).empty() || validate(s).front().severity != SettingsIssue::Severity::Error);
        const Agreement a = agreement(m_headless->renderer(), s, QSize(160, 90));
        QVERIFY(a.counted > 500);
        QVERIFY2(a.referenceShadowed > 0.003 * a.counted, "the square casts no shadow on the ground");
        QVERIFY(a.falseLight + a.falseShadow <= 0.03 * a.referenceShadowed + 0.004 * a.counted);
    }

    void missingTextureWarnsAndUsesTheBaseColour()
    {
        QTemporaryDir dir;
        const QString folder = model("glTF2/BoxTextured-glTF/");
        const QString path = writeFile(dir, "BoxTextured.gltf", readFile(folder + "BoxTextured.gltf"));
        writeFile(dir, "BoxTextured0.bin", readFile(folder + "BoxTextured0.bin"));
        const Scene scene = importModel(path);
        QCOMPARE(int(triangleCount(scene)), 12);
        QVERIFY2(scene.warnings.join(" ").contains("CesiumLogoFlat.png"), qPrintable(scene.warnings.join(" ")));
        for (const SceneObject& o : scene.objects)
            QVERIFY(o.texture == TextureKind::Flat);
    }

    // Node animations play as whole nodes moving: each moving object is where its model says at 0,
    // somewhere else later, over a clip as long as the file's.
    void animatedModelsMove_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("moving");        // objects with a motion
        QTest::addColumn<double>("clip");       // seconds
        QTest::addColumn<QString>("says");      // in the warnings, or empty
        QTest::newRow("LWS slide along x") << model("LWS/move_x.lws") << 1 << 2.0 << QString();
        QTest::newRow("3DS turning cube, no tick rate (25 a second)") << model("3DS/RotatingCube.3DS") << 1 << 181.0 / 25.0 << QString();
        QTest::newRow("ASE child of an animated parent") << model("ASE/CameraRollAnimWithChildObject.ase") << 1 << 4.0 << QString();
        QTest::newRow("ASE motion-capture hierarchy") << model("ASE/MotionCaptureROM.ase") << 26 << 216800.0 / 4800.0 << QString();
        QTest::newRow("COLLADA full turns between keys") << model("Collada/anims_with_full_rotations_between_keys.DAE") << 64 << 11.9667 << QString();
        QTest::newRow("BVH over 4096 key times, skinned") << model("BVH/01_03.bvh") << 1 << 4510.0 / 120.0
                                                         << QStringLiteral("taken at 4096 even times");
    }

    void animatedModelsMove()
    {
        QFETCH(QString, file);
        QFETCH(int, moving);
        QFETCH(double, clip);
        QFETCH(QString, says);
        const Scene scene = importModel(file);
        const int count = int(std::count_if(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.motion.has_value(); }));
        QCOMPARE(count, moving);
        QVERIFY2(std::abs(scene.clipLength() - clip) < 1e-4 * clip, qPrintable(QString::number(scene.clipLength(), 'g', 10)));
        QVERIFY2(says.isEmpty() || scene.warnings.join(" ").contains(says), qPrintable(scene.warnings.join("\n")));
        for (const SceneObject& o : scene.objects) {
            if (!o.motion)
                continue;
            QCOMPARE(motionProblem(*o.motion), QString());
            QVERIFY(o.motion->keys.size() <= kMaxMotionKeys);
            QVERIFY(o.model == o.motion->at(0.0));
            double moved = 0.0;
            for (int i = 1; i < 64; ++i)
                moved = std::max(moved, difference(o.motion->at(clip * i / 64.0), o.model));
            QVERIFY2(moved > 1e-6, qPrintable(o.name));
        }
    }

    // The file's own numbers: LightWave's keys at 30 frames a second, x from 0 to 2.069 at frame 20.
    void keysPlayAtTheirTimes()
    {
        const Scene scene = importModel(model("LWS/move_x.lws"));
        QCOMPARE(scene.objects.size(), std::size_t(1));
        const Motion& motion = *scene.objects[0].motion;
        const glm::dvec3 moved = glm::dvec3(motion.at(20.0 / 30.0)[3]) - glm::dvec3(motion.at(0.0)[3]);
        QVERIFY2(glm::length(moved - glm::dvec3(2.0691125, 0.0, 0.0)) < 1e-5,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(moved.x).arg(moved.y).arg(moved.z)));
    }

    // A node under an animated node moves with it: its placement is the product down the
    // hierarchy, each animated node at its own keys; what the importer puts above the hierarchy
    // (here a scale into range) is the motion's fixed `pre`. A mirrored, flattened or stretched
    // parent keeps its child's placement whole through the keys' position, rotation and scale.
    void nodeAnimationsFollowTheHierarchy_data()
    {
        QTest::addColumn<double>("unit");
        QTest::addColumn<double>("armScaleX");
        QTest::newRow("1 unit") << 1.0 << 1.0;
        QTest::newRow("1e6 units, scaled into range") << 1e6 << 1.0;
        QTest::newRow("arm mirrored") << 1.0 << -1.0;
        QTest::newRow("arm flattened to nothing along x") << 1.0 << 0.0;
        QTest::newRow("arm stretched along x") << 1.0 << 3.0;
    }

    void nodeAnimationsFollowTheHierarchy()
    {
        QFETCH(double, unit);
        QFETCH(double, armScaleX);
        QTemporaryDir dir;
        const Scene scene = importModel(writeFile(dir, "arm.gltf", armGltf(unit, armScaleX)));
        QCOMPARE(scene.objects.size(), std::size_t(1));
        const SceneObject& box = scene.objects[0];
        QVERIFY(box.motion);
        QVERIFY2(scene.warnings.join(" ").contains("only the first, 'Wave', plays"), qPrintable(scene.warnings.join("\n")));
        QCOMPARE(scene.clipLength(), 3.0);
        QVERIFY(box.model == box.motion->at(0.0));
        QCOMPARE(box.motion->pre == glm::dmat4(1.0), unit == 1.0);
        const glm::dmat4 unscaled = glm::inverse(box.motion->pre);
        // At every key time of the arm or the box, and before the arm's first (its rest held); the
        // last key, at the clip's end, is where the cycle starts again, so it is read as a key.
        for (const double t : {0.0, 0.5, 1.0, 2.0}) {
            const double off = difference(unscaled * box.motion->at(t), armBoxAt(t, unit, armScaleX));
            QVERIFY2(off < 1e-6 * unit, qPrintable(QStringLiteral("%1 off by %2 at %3 s").arg(box.name).arg(off).arg(t)));
        }
        const MotionKey last = pathKeyAt(*box.motion, 3.0);
        const glm::dmat4 end = glm::translate(glm::dmat4(1.0), last.position) * glm::mat4_cast(last.rotation) * glm::scale(glm::dmat4(1.0), last.scale);
        QVERIFY2(difference(end, armBoxAt(3.0, unit, armScaleX)) < 1e-6 * unit, qPrintable(QString::number(difference(end, armBoxAt(3.0, unit, armScaleX)))));
        QVERIFY(difference(box.motion->at(3.5), box.motion->at(0.5)) < 1e-9 * unit);     // it repeats after the clip
    }

    // A model nothing moves has no motion; an animation that does not move a mesh's node (a
    // camera's, a morph, a skeleton's bones) leaves it still, said where something is not played.
    void stillModelsHaveNoMotion_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("says");      // in the warnings, or empty for no word of animation
        QTest::newRow("OBJ box") << model("OBJ/box.obj") << QString();
        QTest::newRow("glTF 2 textured box") << model("glTF2/BoxTextured-glTF/BoxTextured.gltf") << QString();
        QTest::newRow("3DS camera animation") << model("3DS/CameraRollAnim.3ds") << QString();
        QTest::newRow("glTF 2 morph animation") << model("glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf")
                                               << QStringLiteral("animation 'Square' changes mesh shapes");
        QTest::newRow("X, three animations of bones") << model("X/Testwuson.X") << QStringLiteral("3 animations; only the first, 'Wuson_Run', plays");
    }

    void stillModelsHaveNoMotion()
    {
        QFETCH(QString, file);
        QFETCH(QString, says);
        const Scene scene = importModel(file);
        QVERIFY(!scene.moves());
        QCOMPARE(scene.clipLength(), 0.0);
        const QString warnings = scene.warnings.join("\n");
        if (says.isEmpty())
            QVERIFY2(!warnings.contains("animation"), qPrintable(warnings));
        else
            QVERIFY2(warnings.contains(says), qPrintable(warnings));
    }

    // Skins are not deformed: a skinned mesh is drawn in its bind pose, and the warning says so.
    void skinnedMeshesAreDrawnInTheirBindPose_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("says");
        QTest::newRow("glTF 2 simple skin") << model("glTF2/simple_skin/simple_skin.gltf") << QStringLiteral("1 of 1 meshes are skinned");
        QTest::newRow("MD5 cube") << model("MD5/SimpleCube.md5mesh") << QStringLiteral("1 of 1 meshes are skinned");
        QTest::newRow("X, animated bones") << model("X/anim_test.x") << QStringLiteral("1 of 1 meshes are skinned");
        QTest::newRow("X, three skinned meshes") << model("X/BCN_Epileptic.X") << QStringLiteral("3 of 3 meshes are skinned");
    }

    void skinnedMeshesAreDrawnInTheirBindPose()
    {
        QFETCH(QString, file);
        QFETCH(QString, says);
        const QStringList warnings = importModel(file).warnings;
        const QString skins = warnings.filter("skinned").join("\n");
        QVERIFY2(skins.contains(says) && skins.contains("does not deform skins") && skins.contains("bind pose"), qPrintable(warnings.join("\n")));
        QCOMPARE(warnings.filter("skinned").size(), 1);
    }

    // A sweep means the same on a 250-unit spider as on the seed: its lights are placed at the
    // model's scale around its target (not inside it), its bias grid is in texels.
    void sweepsFollowTheModelsSize()
    {
        const QString spider = model("OBJ/spider.obj");
        const Settings base = presetSettings(spider);
        const Bounds models = loadSceneFile(spider)->modelBounds();
        const double radius = glm::length(models.max - models.min) * 0.5;
        int placed = 0;
        for (const SweepEntry& entry : loadSweep(QStringLiteral("lights"), base)) {
            const Settings s = applySweepEntry(base, entry);
            if (entry.label.startsWith("defaults @ (-2, 4, -1)")) {
                QVERIFY2(glm::length(s.light.position - models.center()) > radius, qPrintable(entry.label));
                QVERIFY2(entry.label.contains(QChar(0x00D7)), qPrintable(entry.label));     // "× 54.3": the scale is said
                ++placed;
            }
        }
        QCOMPARE(placed, 1);
        for (const SweepEntry& entry : loadSweep(QStringLiteral("bias"), base)) {
            if (entry.label.endsWith("texels"))
                QVERIFY(applySweepEntry(base, entry).bias.space == BiasSpace::Texel);
            QVERIFY2(!entry.label.contains(" wu"), qPrintable(entry.label));
        }
    }

    void largeMeshesAreSplitForCulling()
    {
        // A 300 x 300 x 2 grid of triangles: split into pieces no bigger than the chunk size.
        QTemporaryDir dir;
        QByteArray obj;
        const int n = 300;
        for (int z = 0; z <= n; ++z)
            for (int x = 0; x <= n; ++x)
                obj += QStringLiteral("v %1 %2 %3\n").arg(x * 0.1).arg(std::sin(x * 0.3) * 0.2).arg(z * 0.1).toUtf8();
        for (int z = 0; z < n; ++z) {
            for (int x = 0; x < n; ++x) {
                const int a = z * (n + 1) + x + 1, b = a + 1, c = a + n + 1, d = c + 1;
                obj += QStringLiteral("f %1 %2 %3\nf %2 %4 %3\n").arg(a).arg(c).arg(b).arg(d).toUtf8();
            }
        }
        const Scene scene = importModel(writeFile(dir, "grid.obj", obj));
        QCOMPARE(int(triangleCount(scene)), 2 * n * n);
        QVERIFY(scene.meshes.size() >= std::size_t(2 * n * n) / kMeshChunkTriangles);
        for (const Mesh& mesh : scene.meshes)
            QVERIFY(mesh.indices.size() / 3 <= kMeshChunkTriangles);
    }

    void sceneFilePlacesModelsAndSetsKeys()
    {
        QTemporaryDir dir;
        const QString box = model("OBJ/box.obj");
        const QString path = writeFile(dir, "two.json", QStringLiteral(R"({
            "models": [ { "file": "%1", "position": [0, 1, 0] },
                        { "file": "%1", "position": [3, 0.5, 0], "scale": 2, "casts": false } ],
            "ground": -1.0,
            "light.position": [1, 8, 2],
            "filter.mode": "hard"
        })").arg(box).toUtf8());
        const Scene scene = buildScene(QFileInfo(path).absoluteFilePath());
        QCOMPARE(int(triangleCount(scene)), 24);
        QCOMPARE(scene.groundHeight.value_or(0.0), -1.0);
        QStringList casting;
        for (const SceneObject& o : scene.objects)
            casting << QString("%1 at x %2: %3").arg(o.name).arg(o.model[3][0]).arg(o.castsShadow);
        const auto nonCasters = std::count_if(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return !o.castsShadow; });
        QVERIFY2(nonCasters == 1, qPrintable(casting.join("; ")));     // the second box
        const Settings s = presetSettings(QFileInfo(path).absoluteFilePath());
        QVERIFY(s.light.position == glm::dvec3(1, 8, 2));
        QVERIFY(s.filter.mode == FilterMode::Hard);

        const QString bad = writeFile(dir, "bad.json", R"({"models": [{"file": "nothere.obj"}]})");
        try {
            buildScene(QFileInfo(bad).absoluteFilePath());
            QFAIL("a scene file naming a missing model loaded");
        } catch (const SceneFileError& e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains("nothere.obj"), e.what());
        }
    }

    void receivesFalseKeepsAModelLit_data()
    {
        QTest::addColumn<bool>("receives");
        QTest::newRow("slab receives") << true;
        QTest::newRow("slab does not receive") << false;
    }

    // A box over a wide slab, the light above and behind it: the slab shows the box's shadow
    // unless the scene file says it does not receive, and then it is lit and not measured.
    void receivesFalseKeepsAModelLit()
    {
        QFETCH(bool, receives);
        QTemporaryDir dir;
        const QString path = writeFile(dir, "slab.json", QStringLiteral(R"({
            "models": [ { "file": "%1", "position": [0, 1, 0] },
                        { "file": "%1", "position": [0, 0, 0], "scale": [6, 0.02, 6], "receives": %2 } ],
            "ground": false,
            "light.position": [0.5, 6, -6], "light.target": [0, 0, 0],
            "camera.position": [0, 6, 4], "camera.target": [0, 0, 0]
        })").arg(model("OBJ/box.obj"), receives ? "true" : "false").toUtf8());
        const Settings s = presetSettings(QFileInfo(path).absoluteFilePath());
        Renderer& renderer = m_headless->renderer();
        const VisibilityBuffer buffer = probe::visibility(renderer, s, QSize(160, 90));
        int notReceiving = 0, shadowed = 0;
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            if (buffer.mask(i) == VisibilityBuffer::NotReceiving) {
                ++notReceiving;
                QCOMPARE(buffer.visibility(i), 1.0f);
            }
            shadowed += buffer.mask(i) == VisibilityBuffer::FacingLight && buffer.visibility(i) < 0.5f;
        }
        QCOMPARE(notReceiving > 1000, !receives);
        QCOMPARE(shadowed > 100, receives);
        const Agreement a = agreement(renderer, s, QSize(160, 90));
        QVERIFY(a.falseLight + a.falseShadow <= 0.02 * a.referenceShadowed + 0.004 * a.counted);
    }

    void referenceCacheKeysOnContent()
    {
        QTemporaryDir dir;
        const QByteArray bytes = readFile(model("PLY/cube.ply"));
        const QString a = writeFile(dir, "a.ply", bytes);
        const QString b = writeFile(dir, "renamed copy.ply", bytes);
        Settings sa = presetSettings(QFileInfo(a).absoluteFilePath());
        Settings sb = sa;
        sb.scene = QFileInfo(b).absoluteFilePath();
        QCOMPARE(referenceKeyFor(sa, QSize(64, 64), 4), referenceKeyFor(sb, QSize(64, 64), 4));
        QVERIFY(referenceKeyFor(sa, QSize(64, 64), 4).scene.startsWith("sha256:"));
        // The same name with other content is another scene (the cache notices the new file).
        const QString c = writeFile(dir, "c.obj", squareObj(1.0));
        Settings sc = presetSettings(QFileInfo(c).absoluteFilePath());
        const ReferenceKey before = referenceKeyFor(sc, QSize(64, 64), 4);
        QTest::qWait(1100);     // a new modification time
        writeFile(dir, "c.obj", squareObj(2.0));
        QVERIFY(!(referenceKeyFor(sc, QSize(64, 64), 4) == before));
        QVERIFY(!(referenceKeyFor(sa, QSize(64, 64), 4) == before));
    }

    // A model opened in the window has its bias tuned against the reference in the background:
    // where the tuner finds a clearly better bias it is set as one undo step, and the dock says
    // what it chose and why; otherwise the dock says the defaults stay. Unchecked, nothing runs.
    void openedModelsBiasIsTunedAsOneUndoStep()
    {
        using Side = MainWindow::Side;
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* dock = window.findChild<AccuracyDock*>();
        auto* note = window.findChild<QLabel*>(QStringLiteral("tuningResult"));
        auto* onOpen = window.findChild<QCheckBox*>(QStringLiteral("tuneOnOpen"));
        QVERIFY(dock && note && onOpen);
        onOpen->setChecked(true);
        const auto openAndTune = [&](const QString& path) {
            note->setText(QString());
            window.openSceneInBackground(path);
            QTRY_COMPARE_WITH_TIMEOUT(window.settings(Side::A).scene, path, 60000);
            QTRY_VERIFY_WITH_TIMEOUT(note->text().startsWith("Tuned as the model opened") && !dock->isBusy(), 240000);
            qInfo().noquote() << note->text();
        };
        // A scene file whose own keys leave acne (no bias, front faces in the map), opened on a
        // side without the footprint's clearance and with floors in the map (a side keeps its
        // technique's settings when a scene opens, movedToScene): the tuner finds a clearly
        // better bias and sets it, one undo step.
        const Settings side = window.settings(Side::A);
        Settings bare = side;
        bare.bias.footprint = false;
        bare.bias.skipFloors = false;
        window.setSettings(Side::A, bare);
        QTemporaryDir dir;
        const QString acne = writeFile(dir, "acne.json", QStringLiteral(R"({"models": [{"file": "%1"}], "bias.cull_front": false,
            "bias.footprint": false, "bias.skip_floors": false, "bias.slope": 0, "bias.min": 0})").arg(model("Collada/duck.dae")).toUtf8());
        openAndTune(acne);
        const BiasSettings asOpened = presetSettings(acne).bias;
        const BiasSettings tuned = window.settings(Side::A).bias;
        QVERIFY(tuned.slope + tuned.min > 0.0);     // the file's own bias is 0/0
        QVERIFY2(note->text().contains("Undo"), qPrintable(note->text()));
        QCOMPARE(window.undoStack(Side::A)->undoText(), QStringLiteral("Tune bias for the model"));
        window.undoStack(Side::A)->undo();
        const BiasSettings undone = window.settings(Side::A).bias;
        QVERIFY(undone.slope == asOpened.slope && undone.min == asOpened.min && undone.space == asOpened.space);
        // A model whose defaults already sit on the knee keeps them, and the dock says so.
        Settings restored = window.settings(Side::A);
        restored.bias.footprint = side.bias.footprint;
        restored.bias.skipFloors = side.bias.skipFloors;
        window.setSettings(Side::A, restored);
        const QString duck = model("Collada/duck.dae");
        openAndTune(duck);
        QCOMPARE(window.settings(Side::A).bias, presetSettings(duck).bias);
        QVERIFY2(note->text().contains("stay"), qPrintable(note->text()));

        // Unchecked (and remembered so), opening another model tunes nothing.
        onOpen->setChecked(false);
        note->setText(QString());
        const QString box = model("OBJ/box.obj");
        window.openSceneInBackground(box);
        QTRY_COMPARE(window.settings(Side::A).scene, box);
        QTest::qWait(200);
        QVERIFY(!dock->isBusy() && note->text().isEmpty());
        onOpen->setChecked(true);
    }

    // A shown model saved again by another program is read again and drawn with the settings as
    // they are: no undo step, the camera kept. An editor that writes a new file and renames it over
    // the old one is followed as well as one that writes in place. Saved broken, the last good
    // version stays and the status bar says why.
    void aShownFileChangedOnDiskIsReadAgain()
    {
        using Side = MainWindow::Side;
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("part.obj"));
        const auto save = [&](const QString& from, bool renamedOver) {
            QFile source(from);
            QVERIFY(source.open(QIODevice::ReadOnly));
            const QByteArray bytes = source.readAll();
            const QString written = renamedOver ? dir.filePath(QStringLiteral("part.obj.tmp")) : path;
            QFile out(written);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            QCOMPARE(out.write(bytes), qint64(bytes.size()));
            out.close();
            if (renamedOver) {
                QVERIFY(QFile::remove(path));
                QVERIFY(QFile::rename(written, path));
            }
        };
        save(model("OBJ/box.obj"), false);
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.openScene(path), QString());
        const Renderer* renderer = window.sceneView(Side::A)->renderer();
        const auto drawnTriangles = [&] { return renderer && renderer->scene() ? triangleCount(*renderer->scene()) : std::size_t(0); };
        QTRY_COMPARE(drawnTriangles(), triangleCount(*loadSceneFile(model("OBJ/box.obj"))));
        const Settings before = window.settings(Side::A);
        const int undoSteps = window.undoStack(Side::A)->count();

        save(model("OBJ/WusonOBJ.obj"), true);
        QTRY_COMPARE_WITH_TIMEOUT(drawnTriangles(), triangleCount(*loadSceneFile(model("OBJ/WusonOBJ.obj"))), 30000);
        QCOMPARE(window.settings(Side::A), before);
        QCOMPARE(window.undoStack(Side::A)->count(), undoSteps);
        QVERIFY2(window.statusMessage().contains(QStringLiteral("part.obj changed on disk")), qPrintable(window.statusMessage()));

        save(model("OBJ/concave_polygon.obj"), false);    // still watched after the rename
        QTRY_COMPARE_WITH_TIMEOUT(drawnTriangles(), triangleCount(*loadSceneFile(model("OBJ/concave_polygon.obj"))), 30000);

        const std::size_t good = drawnTriangles();
        save(model("invalid/empty.obj"), false);
        QTRY_VERIFY_WITH_TIMEOUT(window.statusMessage().contains(QStringLiteral("the last good version stays")), 30000);
        window.sceneView(Side::A)->update();
        QTest::qWait(100);
        QCOMPARE(drawnTriangles(), good);
        QCOMPARE(window.settings(Side::A), before);
        // Whoever reads it next (a wipe, a measurement) gets the last good version too, until
        // the file is saved again.
        QCOMPARE(triangleCount(*loadSceneFile(path)), good);
        save(model("OBJ/box.obj"), false);
        QTRY_COMPARE_WITH_TIMEOUT(drawnTriangles(), triangleCount(*loadSceneFile(model("OBJ/box.obj"))), 30000);
    }

    void windowKeepsItsSceneOnABadFile()
    {
        MainWindow window(MainWindow::Persistence::None);
        window.resize(640, 400);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const Settings before = window.settings(MainWindow::Side::A);
        const QString error = window.openScene(model("invalid/empty.obj"));
        QVERIFY2(error.contains("empty.obj"), qPrintable(error));
        QCOMPARE(window.settings(MainWindow::Side::A), before);
        QVERIFY(window.recentScenes().isEmpty());

        const QString good = model("OBJ/box.obj");
        QCOMPARE(window.openScene(good), QString());
        QCOMPARE(window.settings(MainWindow::Side::A).scene, good);
        QCOMPARE(window.recentScenes(), QStringList{good});
        QVERIFY(window.action("openSceneAction"));
        QCOMPARE(window.action("openSceneAction")->shortcut(), QKeySequence(QKeySequence::Open));
        QTRY_VERIFY(drawsScene(window, good));
        // A bad file after a good one keeps the good one.
        QVERIFY(!window.openScene("/nonexistent.glb").isEmpty());
        QCOMPARE(window.settings(MainWindow::Side::A).scene, good);

        // A file dropped on the scene view opens like File → Open Scene.
        const QString dropped = model("PLY/cube.ply");
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(dropped)});
        SceneView* view = window.sceneView(MainWindow::Side::A);
        const QPointF centre(view->width() / 2.0, view->height() / 2.0);
        QDragEnterEvent enter(centre.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(centre, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &drop);
        // Read in the background: the window answers meanwhile, and takes the scene when it is ready.
        QTRY_COMPARE(window.settings(MainWindow::Side::A).scene, dropped);
        QCOMPARE(window.recentScenes(), (QStringList{dropped, good}));
    }

    void compareModeOpensAModelForBothSides()
    {
        using Side = MainWindow::Side;
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.setCompareMode(true);
        window.selectSide(Side::B);
        Settings b = window.settings(Side::B);
        applySetting(b, "filter.mode", "pcf");
        applySetting(b, "bias.space", "texel");
        applySetting(b, "bias.slope", "1.5");
        window.setSettings(Side::B, b);
        const Settings seedA = window.settings(Side::A), seedB = window.settings(Side::B);

        // The scene is what both sides look at; the settings are what they compare.
        const QString engine = model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
        QCOMPARE(window.openScene(engine), QString());
        const Settings a = window.settings(Side::A), opened = window.settings(Side::B);
        QCOMPARE(a.scene, engine);
        QCOMPARE(opened.scene, engine);
        QVERIFY(a.light == opened.light);
        QVERIFY(a.camera == opened.camera);
        QVERIFY(a.light.position != seedA.light.position);
        QVERIFY(a.filter.mode == FilterMode::HwBilinear);
        QVERIFY(opened.filter.mode == FilterMode::Pcf);
        // A bias in world units follows the model's size; one in texels means the same anywhere.
        QVERIFY2(a.bias.min > seedA.bias.min * 10.0, qPrintable(QString::number(a.bias.min)));
        QVERIFY(opened.bias.space == BiasSpace::Texel);
        QCOMPARE(opened.bias.slope, 1.5);
        QVERIFY2(a.shadow.distance > seedA.shadow.distance, "the cascades' reach follows the model's size");
        QTRY_VERIFY(drawsScene(window, engine));

        // One undo step brings the seed back on both sides.
        window.undoStack(Side::B)->undo();
        QCOMPARE(window.settings(Side::A).scene, seedA.scene);
        QVERIFY(window.settings(Side::B) == seedB);
        window.undoStack(Side::B)->redo();
        QCOMPARE(window.settings(Side::A).scene, engine);

        // Leaving compare mode keeps the model just opened.
        window.setCompareMode(false);
        QCOMPARE(window.settings(Side::A).scene, engine);

        // Choosing a preset in the dock moves both sides as well.
        window.setCompareMode(true);
        window.selectSide(Side::A);
        auto* combo = window.findChild<QComboBox*>(QStringLiteral("scene"));
        QVERIFY(combo);
        combo->setCurrentIndex(combo->findText(QStringLiteral("torus")));
        QCOMPARE(window.settings(Side::A).scene, QStringLiteral("torus"));
        QCOMPARE(window.settings(Side::B).scene, QStringLiteral("torus"));
        QVERIFY(window.settings(Side::B).filter.mode == FilterMode::Pcf);
    }

    // Every warning of a file opened in the window is reachable, whole: a button in the status
    // bar counts them and lists them, where the status line shows only the first.
    void everyWarningOfAnOpenedFileIsListed()
    {
        QTemporaryDir dir;
        const QString folder = model("glTF2/BoxTextured-glTF/");
        writeFile(dir, "first.gltf", readFile(folder + "BoxTextured.gltf"));
        writeFile(dir, "second.gltf", readFile(folder + "BoxTextured.gltf").replace("CesiumLogoFlat.png", "AnotherMissing.png"));
        writeFile(dir, "BoxTextured0.bin", readFile(folder + "BoxTextured0.bin"));
        const QString scene = writeFile(dir, "two.json", R"({"models": [{"file": "first.gltf"}, {"file": "second.gltf", "position": [3, 0, 0]}]})");
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.openScene(scene), QString());
        const QStringList warnings = window.warnings();
        QVERIFY2(warnings.size() >= 2, qPrintable(warnings.join(" | ")));
        QVERIFY(warnings.join(" ").contains("CesiumLogoFlat.png") && warnings.join(" ").contains("AnotherMissing.png"));
        auto* button = window.findChild<QToolButton*>(QStringLiteral("warningsButton"));
        QVERIFY(button && button->isVisibleTo(&window));
        QCOMPARE(button->text(), QString::number(warnings.size()));
        QCOMPARE(button->menu()->actions().size(), warnings.size());
        // Undone, another scene is shown: the file's warnings go with it.
        window.undoStack(MainWindow::Side::A)->undo();
        QTRY_VERIFY(!window.warnings().join(" ").contains("AnotherMissing.png"));
        // A clean file next: its own warnings, none, replace any.
        QCOMPARE(window.openScene(scene), QString());
        QVERIFY(window.warnings().join(" ").contains("AnotherMissing.png"));
        QCOMPARE(window.openScene(model("OBJ/spider.obj")), QString());
        QTRY_VERIFY(!window.warnings().join(" ").contains("AnotherMissing.png"));
    }

    // A model opens whole in the scene view it is shown in, whatever that view's shape: the
    // default window's view is taller than wide, and a camera its file frames for 16:9 cuts a
    // model off in a narrower one. View > Reset Camera and R frame it the same way.
    void openedModelsAreFramedWholeInTheView()
    {
        using Side = MainWindow::Side;
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        SceneView* view = window.sceneView(Side::A);
        // Whether every corner of the models' bounds lies inside a view of `aspect` from `camera`.
        const auto whole = [&](const QString& path, const CameraSettings& camera, double aspect) {
            const Bounds models = loadSceneFile(path)->modelBounds();
            const CameraFrame frame = computeCameraFrame(camera, aspect, models);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::dvec3 p{corner & 1 ? models.max.x : models.min.x, corner & 2 ? models.max.y : models.min.y,
                                   corner & 4 ? models.max.z : models.min.z};
                const glm::dvec4 clip = frame.viewProjection * glm::dvec4(p, 1.0);
                if (clip.w <= 0.0 || std::abs(clip.x) > clip.w || std::abs(clip.y) > clip.w)
                    return false;
            }
            return true;
        };
        const QString spider = model("OBJ/spider.obj");
        // The default window, then one whose view is narrower still.
        for (const QSize size : {QSize(1200, 750), QSize(1000, 850)}) {
            window.resize(size);
            QTRY_VERIFY(view->width() < view->height());
            const double aspect = view->aspect();
            for (const QString& path : {spider, model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb")}) {
                QCOMPARE(window.openScene(path), QString());
                QTRY_VERIFY(drawsScene(window, QFileInfo(path).absoluteFilePath()));
                keepPicture(&window, QStringLiteral("framed-%1-%2").arg(QFileInfo(path).baseName()).arg(size.width()));
                // The caption above the view may take another line for the new scene: the
                // aspect it is framed for is within a few per cent of the view's now, which the
                // framing's margin covers.
                const CameraSettings opened = window.settings(Side::A).camera;
                QVERIFY2(whole(path, opened, view->aspect()), qPrintable(QStringLiteral("%1 is cropped in a %2:1 view").arg(path).arg(view->aspect())));
                // Reset Camera frames it for the view as it is, after a dolly.
                Settings s = window.settings(Side::A);
                s.camera.position = opened.target + (opened.position - opened.target) * 0.3;
                window.setSettings(Side::A, s);
                QVERIFY(!whole(path, s.camera, view->aspect()));
                view->setFocus();
                QTest::keyClick(view, Qt::Key_R);
                QVERIFY(window.settings(Side::A).camera == presetCamera(path, view->aspect()));
                QVERIFY(whole(path, window.settings(Side::A).camera, view->aspect()));
            }
            // The file's own framing, for 16:9, crops the spider in the narrower view.
            if (size.width() < 1200)
                QVERIFY(!whole(spider, presetSettings(spider).camera, aspect));
        }
    }

    // On an 850-unit engine the light's controls span the engine, not the seed's ±10 units, and
    // a directional light turns by its direction: fields, or a Ctrl+drag in the view.
    void lightControlsFitTheScene()
    {
        using Side = MainWindow::Side;
        const std::unique_ptr<MainWindow> shown = shownWindow();
        MainWindow& window = *shown;
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QString engine = model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
        QCOMPARE(window.openScene(engine), QString());
        QTRY_VERIFY(drawsScene(window, engine));
        PropertiesDock* dock = window.propertiesDock();
        QTRY_VERIFY(dock->findChild<SliderSpinBox*>("light.target.x")->slider()->maximum() > 0);
        // No slider of a position sits pinned at an end of its span.
        for (const char* name : {"light.target.x", "light.target.y", "light.target.z", "camera.position.x", "camera.position.y",
                                 "camera.position.z", "light.distance"}) {
            QSlider* slider = dock->findChild<SliderSpinBox*>(name)->slider();
            QVERIFY2(slider->value() > slider->minimum() && slider->value() < slider->maximum(),
                     qPrintable(QStringLiteral("%1 at %2 of [%3, %4]").arg(name).arg(slider->value()).arg(slider->minimum()).arg(slider->maximum())));
        }
        // No slider starts pinned at the end of its span with its field short of the range's:
        // the bias's slope, a model's far plane, its light's reach all have room both ways.
        for (SliderSpinBox* field : dock->findChildren<SliderSpinBox*>()) {
            const QSlider* slider = field->slider();
            const bool pinned = slider->value() == slider->maximum() && field->value() < field->spinBox()->maximum();
            QVERIFY2(!pinned, qPrintable(QStringLiteral("%1 = %2 sits at the end of its slider [%3, %4]")
                                             .arg(field->objectName()).arg(field->value()).arg(field->sliderLow()).arg(field->sliderHigh())));
        }
        // A directional light shows a direction, not a place.
        QVERIFY(!dock->findChild<SliderSpinBox*>("light.position.x")->isVisibleTo(dock));
        auto* azimuth = dock->findChild<SliderSpinBox*>("light.azimuth");
        auto* elevation = dock->findChild<SliderSpinBox*>("light.elevation");
        QVERIFY(azimuth->isVisibleTo(dock) && elevation->isVisibleTo(dock));
        const Settings before = window.settings(Side::A);
        const LightAngles start = lightAngles(before.light.position, before.light.target);
        QVERIFY2(std::abs(azimuth->value() - start.azimuth) < 1e-6, qPrintable(QString::number(azimuth->value())));

        // The elevation typed: the light keeps its azimuth and distance, only rises.
        elevation->spinBox()->setValue(30.0);
        const LightAngles typed = lightAngles(window.settings(Side::A).light.position, before.light.target);
        QVERIFY2(std::abs(typed.elevation - 30.0) < 1e-6 && std::abs(typed.azimuth - start.azimuth) < 1e-6
                     && std::abs(typed.distance - start.distance) < 0.01 * start.distance,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(typed.azimuth).arg(typed.elevation).arg(typed.distance)));

        // Ctrl+drag 25 pixels right: 10 degrees further round, as one undo step.
        SceneView* view = window.sceneView(Side::A);
        const QPoint from(view->width() / 2, view->height() / 2);
        const int steps = window.undoStack(Side::A)->count();
        QTest::mousePress(view, Qt::LeftButton, Qt::ControlModifier, from);
        for (int x = 5; x <= 25; x += 5) {
            QMouseEvent move(QEvent::MouseMove, QPointF(from + QPoint(x, 0)), view->mapToGlobal(QPointF(from + QPoint(x, 0))), Qt::NoButton,
                             Qt::LeftButton, Qt::ControlModifier);
            QApplication::sendEvent(view, &move);
        }
        QTest::mouseRelease(view, Qt::LeftButton, Qt::ControlModifier, from + QPoint(25, 0));
        const LightAngles dragged = lightAngles(window.settings(Side::A).light.position, before.light.target);
        QVERIFY2(std::abs(std::remainder(dragged.azimuth - typed.azimuth, 360.0) - 10.0) < 1e-6, qPrintable(QString::number(dragged.azimuth)));
        QVERIFY(std::abs(dragged.elevation - 30.0) < 1e-6);
        QCOMPARE(window.undoStack(Side::A)->count(), steps + 1);
        QVERIFY(window.settings(Side::A).camera == before.camera);     // the drag turned the light, not the view
        QTRY_VERIFY(std::abs(azimuth->value() - dragged.azimuth) < 1e-6);

        // As a spot light, the place the fields show is where the direction put it.
        auto* type = dock->findChild<QComboBox*>("light.type");
        type->setCurrentIndex(type->findData(QStringLiteral("spot")));
        QVERIFY(window.settings(Side::A).light.type == LightType::Spot);
        const glm::dvec3 placed = window.settings(Side::A).light.position;
        for (int i = 0; i < 3; ++i) {
            auto* box = dock->findChild<SliderSpinBox*>(QStringLiteral("light.position.") + QLatin1Char("xyz"[i]));
            QVERIFY(box->isVisibleTo(dock));
            QVERIFY2(std::abs(box->value() - placed[i]) < 1e-6, qPrintable(QStringLiteral("%1 shows %2, is %3").arg(i).arg(box->value()).arg(placed[i])));
        }
    }

    void init() { if (!m_headless) m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestModelImport)
#include "tst_ModelImport.moc"
