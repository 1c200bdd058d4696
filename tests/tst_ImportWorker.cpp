// Model files are read in a separate process: whatever the worker does (crash, hang, eat
// memory, flood or garble its answer, stop early, get cancelled), the caller gets a refusal that
// names the file and what happened, quickly, and nothing else changes. What comes back is
// checked again; the real worker's scene equals the in-process import.
#include "ImportPayload.h"
#include "IsolatedImport.h"
#include "ModelImporter.h"
#include "SceneFileError.h"
#include "SceneLoader.h"
#include "TestFiles.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <cstring>
#include <thread>

using namespace shadowlab;

namespace {

const QString kModels = kTestModels;

ImportControl fakeControl(double seconds = 3.0)
{
    ImportControl control;
    control.workerProgram = QStringLiteral(SHADOWLAB_FAKE_WORKER);
    control.limits.timeSeconds = seconds;
    control.limits.memoryMiB = 512;
    control.limits.outputMiB = 16;
    return control;
}

// The refusal's message, or a failure when there was none.
QString refusal(const QString& path, const ImportControl& control)
{
    try {
        importModelIsolated(path, control);
    } catch (const SceneFileError& e) {
        return QString::fromUtf8(e.what());
    }
    return QString();
}

// A path out along x and back over 2 s.
Motion outAndBack()
{
    Motion motion;
    motion.kind = Motion::Kind::Path;
    motion.period = 2.0;
    motion.keys = {MotionKey{.time = 0.0}, MotionKey{.time = 1.0, .position = {1.0, 0.0, 0.0}}, MotionKey{.time = 2.0}};
    return motion;
}

std::size_t triangles(const Scene& scene)
{
    std::size_t n = 0;
    for (const Mesh& mesh : scene.meshes)
        n += mesh.indices.size() / 3;
    return n;
}

} // namespace

class tst_ImportWorker : public QObject {
    Q_OBJECT

private slots:
    void workerMisbehaves_data();
    void workerMisbehaves();
    void theParentNamesTheScene();
    void cancelStopsAtOnce();
    void progressArrives();
    void realWorkerMatchesInProcess_data();
    void realWorkerMatchesInProcess();
    void realWorkerRefusesLikeInProcess();
    void realWorkerUnderAHang();
    void untrustedAnswer_data();
    void untrustedAnswer();
    void limitsValidate();
    void refusalsSayWhichLimitStoppedThem();
    void headerCountsAreCheckedBeforeReading();
};

void tst_ImportWorker::workerMisbehaves_data()
{
    QTest::addColumn<QByteArray>("mode");
    QTest::addColumn<QString>("says");
    QTest::addColumn<double>("seconds");    // the time limit
    QTest::newRow("crash") << QByteArray("crash") << QStringLiteral("crashed reading it (signal 11") << 1.5;
    QTest::newRow("abort") << QByteArray("abort") << QStringLiteral("crashed reading it (signal 6") << 1.5;
    QTest::newRow("busy forever") << QByteArray("spin") << QStringLiteral("took longer than 1.5 s") << 1.5;
    QTest::newRow("asleep forever") << QByteArray("sleep") << QStringLiteral("took longer than 1.5 s") << 1.5;
    // The memory limit stops it long before the machine's memory: an allocation fails (under
    // AddressSanitizer too, where a limit on resident memory stands in for the address space's).
    QTest::newRow("eats memory") << QByteArray("memory") << QStringLiteral("crashed reading it (signal 6") << 20.0;
    QTest::newRow("garbage") << QByteArray("garbage") << QStringLiteral("does not start as an import answer does") << 1.5;
    QTest::newRow("half an answer") << QByteArray("truncated") << QStringLiteral("does not hold together") << 1.5;
    QTest::newRow("bad index") << QByteArray("bad-index") << QStringLiteral("names a vertex a mesh of 24 does not have") << 1.5;
    QTest::newRow("early exit") << QByteArray("exit") << QStringLiteral("stopped without an answer (exit code 3)") << 1.5;
    QTest::newRow("silent") << QByteArray("silent") << QStringLiteral("stopped without an answer") << 1.5;
    QTest::newRow("flood") << QByteArray("flood") << QStringLiteral("more than 16 MiB") << 1.5;
    QTest::newRow("out of memory") << QByteArray("out-of-memory") << QStringLiteral("more memory to read than the import memory limit of 512 MiB") << 1.5;
    QTest::newRow("motion back in time") << QByteArray("backward-motion") << QStringLiteral("the motion of object 'cube': key 2's time must be after key 1's")
                                         << 1.5;
}

void tst_ImportWorker::workerMisbehaves()
{
    QFETCH(QByteArray, mode);
    QFETCH(QString, says);
    QFETCH(double, seconds);
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("engine.ply"), mode + "\n");
    QElapsedTimer clock;
    clock.start();
    const QString message = refusal(path, fakeControl(seconds));
    QVERIFY2(message.contains(says), qPrintable(message));
    QVERIFY2(message.contains(path), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("nothing was changed")) || message.contains(QStringLiteral("damaged")), qPrintable(message));
    QVERIFY2(clock.elapsed() < 12000 + seconds * 1000, qPrintable(QString::number(clock.elapsed())));
}

void tst_ImportWorker::theParentNamesTheScene()
{
    // An answer cannot point the program at another file, nor claim another scene's cached traces.
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("box.glb"), "other-name\n");
    const Scene scene = importModelIsolated(path, fakeControl());
    QCOMPARE(scene.name, QFileInfo(path).absoluteFilePath());
    QVERIFY(scene.identity != "seed");
    QCOMPARE(scene.identity.size(), 64);
    const QString other = writeFile(dir, QStringLiteral("box2.glb"), "other-name\n\n");
    QVERIFY(importModelIsolated(other, fakeControl()).identity != scene.identity);
    QCOMPARE(importModelIsolated(path, fakeControl()).identity, scene.identity);   // and it is stable
}

void tst_ImportWorker::cancelStopsAtOnce()
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("big.glb"), "sleep\n");
    std::atomic<bool> cancel = false;
    ImportControl control = fakeControl(30.0);
    control.cancel = &cancel;
    QElapsedTimer clock;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        clock.start();
        cancel = true;
    });
    bool cancelled = false;
    try {
        importModelIsolated(path, control);
    } catch (const ImportCancelled& e) {
        cancelled = QString::fromUtf8(e.what()).contains(QStringLiteral("cancelled"));
    }
    canceller.join();
    QVERIFY(cancelled);
    QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
}

void tst_ImportWorker::progressArrives()
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("slow.obj"), "slow\n");
    std::vector<double> seen;
    ImportControl control = fakeControl(20.0);
    control.progress = [&](double f) { seen.push_back(f); };
    const Scene scene = importModelIsolated(path, control);
    QCOMPARE(scene.objects.size(), std::size_t(1));
    QVERIFY2(seen.size() >= 10, qPrintable(QString::number(seen.size())));
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    QCOMPARE(seen.back(), 1.0);
}

void tst_ImportWorker::realWorkerMatchesInProcess_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("glb") << kModels + QStringLiteral("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    QTest::newRow("gltf textured") << kModels + QStringLiteral("glTF2/BoxTextured-glTF/BoxTextured.gltf");
    QTest::newRow("obj") << kModels + QStringLiteral("OBJ/spider.obj");
    QTest::newRow("ply") << kModels + QStringLiteral("PLY/cube.ply");
    QTest::newRow("stl") << kModels + QStringLiteral("STL/Spider_ascii.stl");
    QTest::newRow("dae") << kModels + QStringLiteral("Collada/duck.dae");
    QTest::newRow("dae, 64 nodes animated") << kModels + QStringLiteral("Collada/anims_with_full_rotations_between_keys.DAE");
    QTest::newRow("bvh, motion capture of 4096 keys") << kModels + QStringLiteral("BVH/01_03.bvh");
}

void tst_ImportWorker::realWorkerMatchesInProcess()
{
    QFETCH(QString, file);
    QVERIFY2(QFileInfo::exists(file), qPrintable(file));
    const Scene direct = importModel(file);
    const Scene isolated = importModelIsolated(file);
    QCOMPARE(isolated.name, direct.name);
    QCOMPARE(isolated.identity.size(), 64);   // the parent's hash, bound to what the worker read (theParentNamesTheScene)
    QCOMPARE(isolated.warnings, direct.warnings);
    QCOMPARE(isolated.meshes.size(), direct.meshes.size());
    QCOMPARE(isolated.objects.size(), direct.objects.size());
    QCOMPARE(isolated.images.size(), direct.images.size());
    QCOMPARE(triangles(isolated), triangles(direct));
    for (std::size_t m = 0; m < direct.meshes.size(); ++m) {
        QCOMPARE(isolated.meshes[m].indices, direct.meshes[m].indices);
        QCOMPARE(isolated.meshes[m].vertices.size(), direct.meshes[m].vertices.size());
        QVERIFY(std::memcmp(isolated.meshes[m].vertices.data(), direct.meshes[m].vertices.data(),
                            direct.meshes[m].vertices.size() * sizeof(Vertex)) == 0);
    }
    for (std::size_t o = 0; o < direct.objects.size(); ++o) {
        QCOMPARE(isolated.objects[o].mesh, direct.objects[o].mesh);
        QVERIFY(isolated.objects[o].model == direct.objects[o].model);
        QCOMPARE(isolated.objects[o].image, direct.objects[o].image);
        QVERIFY(isolated.objects[o].motion == direct.objects[o].motion);
    }
    for (std::size_t i = 0; i < direct.images.size(); ++i)
        QCOMPARE(isolated.images[i], direct.images[i].convertToFormat(QImage::Format_RGBA8888));
}

void tst_ImportWorker::realWorkerRefusesLikeInProcess()
{
    QTemporaryDir dir;
    const QStringList files = {
        writeFile(dir, QStringLiteral("empty.obj"), QByteArray()),
        writeFile(dir, QStringLiteral("noise.stl"), QByteArray("solid x\nfacet normal what\n")),
        writeFile(dir, QStringLiteral("inflated.ply"), QByteArray("ply\nformat ascii 1.0\nelement vertex 99999999\nproperty float x\nend_header\n1\n")),
        writeFile(dir, QStringLiteral("points.obj"), QByteArray("v 0 0 0\nv 1 0 0\np 1 2\n")),
        // A node scaled beyond a float: its transform is infinite, named by the importer.
        writeFile(dir, QStringLiteral("infinite.gltf"), QByteArray("{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"scale\": [1e+200, 1e+200, 1e+200], \"children\": [1]}, {\"scale\": [1e+200, 1e+200, 1e+200], \"mesh\": 0}], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}], \"buffers\": [{\"byteLength\": 36, \"uri\": \"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}], \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", \"min\": [0, 0, 0], \"max\": [1, 1, 0]}]}")),
        dir.filePath(QStringLiteral("missing.glb")),
    };
    for (const QString& file : files) {
        QString direct;
        try {
            importModel(file);
        } catch (const SceneFileError& e) {
            direct = QString::fromUtf8(e.what());
        }
        QVERIFY2(!direct.isEmpty(), qPrintable(file));
        QCOMPARE(refusal(file, ImportControl{}), direct);
    }
    QVERIFY(refusal(files[4], ImportControl{}).contains(QStringLiteral("has a transform that is not finite numbers")));
}

void tst_ImportWorker::realWorkerUnderAHang()
{
    // A worker that does not answer in time is stopped: the real worker, given a tiny limit, on
    // a model that takes longer than that to read (a 3·10^6-triangle binary STL made here).
    QTemporaryDir dir;
    const quint32 count = 3'000'000;
    QByteArray stl(80, ' ');
    stl.append(reinterpret_cast<const char*>(&count), 4);
    QByteArray facet(50, '\0');
    for (quint32 i = 0; i < count; ++i) {
        float v[12] = {0, 0, 1, float(i), 0, 0, float(i) + 1, 0, 0, float(i), 1, 0};
        std::memcpy(facet.data(), v, sizeof v);
        stl.append(facet);
    }
    const QString path = writeFile(dir, QStringLiteral("big.stl"), stl);
    ImportControl control;
    control.limits.timeSeconds = 1.0;
    QElapsedTimer clock;
    clock.start();
    const QString message = refusal(path, control);
    QVERIFY2(message.contains(QStringLiteral("took longer than 1 s")), qPrintable(message));
    QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));
}

void tst_ImportWorker::untrustedAnswer_data()
{
    QTest::addColumn<QByteArray>("answer");
    QTest::addColumn<QString>("says");
    Scene scene;
    scene.name = QStringLiteral("s");
    scene.meshes.push_back(meshes::cube());
    SceneObject object;
    object.texture = TextureKind::Flat;
    scene.objects.push_back(object);
    const QByteArray good = encodeImportedScene(scene);
    const auto with = [&](auto change) {
        Scene s = scene;
        change(s);
        return encodeImportedScene(s);
    };
    QTest::newRow("good") << good << QString();
    QTest::newRow("empty") << QByteArray() << QStringLiteral("does not start");
    QTest::newRow("one byte short") << good.chopped(1) << QStringLiteral("does not end");
    QTest::newRow("trailing bytes") << good + "xx" << QStringLiteral("2 bytes follow");
    QTest::newRow("NaN position") << with([](Scene& s) { s.meshes[0].vertices[3].position.y = NAN; }) << QStringLiteral("not a finite number");
    QTest::newRow("index out of range") << with([](Scene& s) { s.meshes[0].indices[0] = 24; }) << QStringLiteral("does not have");
    QTest::newRow("partial triangle") << with([](Scene& s) { s.meshes[0].indices.pop_back(); }) << QStringLiteral("not whole triangles");
    QTest::newRow("mesh out of range") << with([](Scene& s) { s.objects[0].mesh = 1; }) << QStringLiteral("names mesh 1 of 1");
    QTest::newRow("texture out of range") << with([](Scene& s) { s.objects[0].texture = TextureKind::Image; s.objects[0].image = 0; })
                                          << QStringLiteral("names texture 0 of 0");
    QTest::newRow("infinite placement") << with([](Scene& s) { s.objects[0].model[3][1] = INFINITY; }) << QStringLiteral("placement is not finite");
    QTest::newRow("no objects") << with([](Scene& s) { s.objects.clear(); }) << QStringLiteral("no objects");
    QTest::newRow("cut-out") << with([](Scene& s) { s.objects[0].alphaCutoff = 0.3f; s.objects[0].baseAlpha = 0.6f; }) << QString();
    QTest::newRow("NaN alpha cut-off") << with([](Scene& s) { s.objects[0].alphaCutoff = NAN; }) << QStringLiteral("alpha cut-off or base alpha");
    QTest::newRow("base alpha above 1") << with([](Scene& s) { s.objects[0].baseAlpha = 2.0f; }) << QStringLiteral("alpha cut-off or base alpha");
    QTest::newRow("empty mesh") << with([](Scene& s) { s.meshes[0].vertices.clear(); s.meshes[0].indices.clear(); }) << QStringLiteral("no triangles");
    QTest::newRow("placed beyond finite") << with([](Scene& s) { s.meshes[0].vertices[0].position.x = 3e38f; s.objects[0].model[0][0] = 1e300; })
                                          << QStringLiteral("beyond finite numbers");
    QTest::newRow("long identity") << with([](Scene& s) { s.identity = QByteArray(4096, 'a'); }) << QStringLiteral("identity is 4096 bytes");
    // A moving object's motion is checked as a scene file's is (motionProblem()).
    const auto moving = [&](auto change) {
        return with([&](Scene& s) {
            s.objects[0].motion = outAndBack();
            s.objects[0].model = s.objects[0].motion->at(0.0);
            change(*s.objects[0].motion);
        });
    };
    QTest::newRow("moving") << moving([](Motion&) {}) << QString();
    QTest::newRow("moving, placed elsewhere") << with([](Scene& s) { s.objects[0].motion = outAndBack(); s.objects[0].model[3][0] = 5.0; })
                                              << QString();
    QTest::newRow("key times not increasing") << moving([](Motion& m) { m.keys[2].time = 1.0; })
                                              << QStringLiteral("key 2's time must be after key 1's");
    QTest::newRow("first key after 0") << moving([](Motion& m) { m.keys[0].time = 0.5; }) << QStringLiteral("first key must be at time 0");
    QTest::newRow("NaN key time") << moving([](Motion& m) { m.keys[1].time = NAN; }) << QStringLiteral("key 1 must hold finite numbers");
    QTest::newRow("NaN key position") << moving([](Motion& m) { m.keys[1].position.y = NAN; }) << QStringLiteral("key 1 must hold finite numbers");
    QTest::newRow("infinite key scale") << moving([](Motion& m) { m.keys[2].scale.z = INFINITY; }) << QStringLiteral("key 2 must hold finite numbers");
    QTest::newRow("rotation not unit") << moving([](Motion& m) { m.keys[1].rotation = glm::dquat(0.5, 0.0, 0.0, 0.0); })
                                       << QStringLiteral("key 1's rotation must be a unit quaternion");
    QTest::newRow("rotation drifted by rounding") << moving([](Motion& m) { m.keys[1].rotation = glm::dquat(1.0 + 1e-5, 0.0, 0.0, 0.0); })
                                                  << QString();
    QTest::newRow("NaN period") << moving([](Motion& m) { m.period = NAN; }) << QStringLiteral("period must be a number of seconds above 0");
    QTest::newRow("path with no keys") << moving([](Motion& m) { m.keys.clear(); }) << QStringLiteral("a path needs at least one key");
    QTest::newRow("infinite fixed placement") << moving([](Motion& m) { m.pre[3][0] = INFINITY; }) << QStringLiteral("fixed placement is not finite");
    QTest::newRow("too many keys") << moving([](Motion& m) {
        m.keys.resize(kMaxMotionKeys + 1);
        for (std::size_t i = 0; i < m.keys.size(); ++i)
            m.keys[i].time = double(i);
        m.period = double(m.keys.size());
    }) << QStringLiteral("motion key count 4097 is over the limit of 4096");
    // A count that promises more than the bytes there are is refused before anything is allocated.
    // The mesh's vertex count: after the header (13 bytes), the name "s" (5), an empty identity
    // (4), no warnings (4), no ground (1), the mesh count (4) and the convex flag (1).
    QByteArray inflated = good;
    const qsizetype vertexCount = 13 + 5 + 4 + 4 + 1 + 4 + 1;
    QCOMPARE(quint8(inflated[vertexCount]), quint8(24));
    inflated[vertexCount + 3] = '\x7f';
    QTest::newRow("vertex count inflated") << inflated << QStringLiteral("more than the answer holds");
    QByteArray kind = good;
    kind[12] = 9;
    QTest::newRow("unknown kind") << kind << QStringLiteral("its kind is 9");
}

void tst_ImportWorker::untrustedAnswer()
{
    QFETCH(QByteArray, answer);
    QFETCH(QString, says);
    QString message;
    try {
        const ImportReply reply = decodeImportReply(answer, QStringLiteral("model.glb"));
        QCOMPARE(reply.scene.meshes.at(0).vertices.size(), std::size_t(24));
        for (const SceneObject& object : reply.scene.objects) {
            if (object.motion)
                QVERIFY(object.model == object.motion->at(0.0));   // where it is at 0 is its motion's to say
        }
    } catch (const SceneFileError& e) {
        message = QString::fromUtf8(e.what());
    }
    if (says.isEmpty()) {
        QVERIFY2(message.isEmpty(), qPrintable(message));
    } else {
        QVERIFY2(message.contains(says), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("'model.glb'")), qPrintable(message));
    }
}

void tst_ImportWorker::limitsValidate()
{
    for (const ImportLimits& bad : {ImportLimits{.timeSeconds = 0.0}, ImportLimits{.timeSeconds = NAN}, ImportLimits{.memoryMiB = 16},
                                    ImportLimits{.outputMiB = 0}}) {
        QVERIFY_THROWS_EXCEPTION(SettingsError, setImportLimits(bad));
    }
    QCOMPARE(importLimits().timeSeconds, 30.0);
    setImportLimits({.timeSeconds = 5.0});
    QCOMPARE(importLimits().timeSeconds, 5.0);
    setImportLimits({});
}

QTEST_GUILESS_MAIN(tst_ImportWorker)

// A file stopped by a limit says which, so that the command line can name its option and the
// window offer a button that raises it; other refusals name none.
void tst_ImportWorker::refusalsSayWhichLimitStoppedThem()
{
    QTemporaryDir dir;
    const auto limitOf = [&](const QByteArray& mode) {
        try {
            importModelIsolated(writeFile(dir, QString::fromLatin1(mode) + QStringLiteral(".ply"), mode + "\n"), fakeControl(1.5));
        } catch (const SceneFileError& e) {
            return e.limit();
        }
        return SceneFileError::Limit::None;
    };
    QCOMPARE(limitOf("sleep"), SceneFileError::Limit::Time);
    QCOMPARE(limitOf("out-of-memory"), SceneFileError::Limit::Memory);
    QCOMPARE(limitOf("crash"), SceneFileError::Limit::None);
    QVERIFY(!refusal(writeFile(dir, "slow.ply", "sleep\n"), fakeControl(1.5)).contains("--import"));   // the front end's words, not the loader's
}

// A count the file's header states is checked before the worker reads a byte: a PLY or OFF of
// 2·10^7 faces is refused at once (the worker here would sleep through its time limit).
void tst_ImportWorker::headerCountsAreCheckedBeforeReading()
{
    QTemporaryDir dir;
    const QString ply = writeFile(dir, "huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 10000000\nproperty float x\n"
                                                   "property float y\nproperty float z\nelement face 20000000\n"
                                                   "property list uchar int vertex_indices\nend_header\n");
    const QString off = writeFile(dir, "huge.off", "OFF\n# a comment\n10000000 20000000 0\n");
    const QString small = writeFile(dir, "small.ply", "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1\nend_header\n");
    QCOMPARE(statedFaceCount(ply), std::optional<std::size_t>(20000000));
    QCOMPARE(statedFaceCount(off), std::optional<std::size_t>(20000000));
    QCOMPARE(statedFaceCount(small), std::optional<std::size_t>(1));
    QCOMPARE(statedFaceCount(writeFile(dir, "any.obj", "v 0 0 0\n")), std::optional<std::size_t>());
    QCOMPARE(statedFaceCount(writeFile(dir, "inline.off", "OFF 8 6 0\n0 0 0\n")), std::optional<std::size_t>(6));
    QCOMPARE(statedFaceCount(writeFile(dir, "vertex.off", "OFF\n  # indented\n1.5 20000000 3\n")), std::optional<std::size_t>());
    for (const QString& path : {ply, off}) {
        QElapsedTimer clock;
        clock.start();
        const QString message = refusal(path, fakeControl(30.0));
        QVERIFY2(message.contains("20,000,000 faces by its header") && message.contains("decimate"), qPrintable(message));
        QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));   // not the 30 s the worker would take
    }
}

#include "tst_ImportWorker.moc"
