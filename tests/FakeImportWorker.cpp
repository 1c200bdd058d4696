// Stands in for shadowlab-import-worker in the tests of the parent's side (tst_ImportWorker,
// tst_MainWindow): the first word of the file it is given says how to misbehave.
#include "ImportPayload.h"
#include "Mesh.h"

#include <QCoreApplication>
#include <QFile>
#include <QThread>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <unistd.h>

using namespace shadowlab;

namespace {

Scene cubeScene(const QString& name)
{
    Scene scene;
    scene.name = name;
    scene.identity = "fake";
    scene.meshes.push_back(meshes::cube());
    SceneObject cube;
    cube.name = QStringLiteral("cube");
    cube.texture = TextureKind::Flat;
    scene.objects.push_back(cube);
    return scene;
}

int g_answerFd = STDOUT_FILENO;

void write(const QByteArray& bytes)
{
    const char* data = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0) {
        const ssize_t written = ::write(g_answerFd, data, std::size_t(left));
        if (written <= 0)
            std::exit(74);
        data += written;
        left -= written;
    }
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    if (app.arguments().size() == 4 && app.arguments().at(2) == u"--answer-fd")
        g_answerFd = app.arguments().at(3).toInt();
    else if (app.arguments().size() != 2)
        return 64;
    const QString path = app.arguments().at(1);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return 66;
    const QByteArray mode = file.readLine().trimmed();

    if (mode == "crash")
        std::raise(SIGSEGV);
    if (mode == "abort")
        std::abort();
    if (mode == "spin") {
        std::atomic<unsigned long> spins = 0;
        for (;;)
            spins.fetch_add(1, std::memory_order_relaxed);
    }
    if (mode == "sleep") {
        for (;;)
            QThread::sleep(1);
    }
    if (mode == "memory") {
        std::vector<char*> blocks;
        for (;;) {
            char* block = static_cast<char*>(std::malloc(std::size_t(64) << 20));
            if (!block)
                std::abort();   // as an importer that does not check would crash
            std::memset(block, 1, std::size_t(64) << 20);
            blocks.push_back(block);
        }
    }
    if (mode == "garbage") {
        QByteArray noise(4096, '\0');
        for (int i = 0; i < noise.size(); ++i)
            noise[i] = char((i * 7919) ^ (i >> 3));
        write(noise);
        return 0;
    }
    if (mode == "exit")
        return 3;
    if (mode == "silent")
        return 0;
    if (mode == "flood") {
        const QByteArray block(1 << 20, 'x');
        for (;;)
            write(block);
    }
    if (mode == "truncated") {
        const QByteArray answer = encodeImportedScene(cubeScene(path));
        write(answer.left(answer.size() / 2));
        return 0;
    }
    if (mode == "bad-index") {
        Scene scene = cubeScene(path);
        scene.meshes[0].indices[4] = 9999;
        write(encodeImportedScene(scene));
        return 0;
    }
    if (mode == "backward-motion") {
        Scene scene = cubeScene(path);
        Motion motion;
        motion.kind = Motion::Kind::Path;
        motion.period = 2.0;
        motion.keys = {MotionKey{.time = 0.0}, MotionKey{.time = 1.5}, MotionKey{.time = 1.0}};
        scene.objects[0].motion = motion;
        write(encodeImportedScene(scene));
        return 0;
    }
    if (mode == "out-of-memory") {
        write(encodeImportRefusal(ImportReplyKind::OutOfMemory, QStringLiteral("an allocation failed")));
        return 0;
    }
    if (mode == "other-name") {
        Scene scene = cubeScene(QStringLiteral("/etc/passwd"));
        scene.identity = "seed";
        write(encodeImportedScene(scene));
        return 0;
    }
    if (mode == "slow") {
        // Progress for about 10 s, then a good answer: what a large model looks like.
        for (int i = 0; i <= 100; ++i) {
            std::fprintf(stderr, "progress %.2f\n", i / 100.0);
            std::fflush(stderr);
            QThread::msleep(100);
        }
        write(encodeImportedScene(cubeScene(path)));
        return 0;
    }
    if (mode == "scene") {
        std::fputs("progress 0.5\n", stderr);
        write(encodeImportedScene(cubeScene(path)));
        return 0;
    }
    return 65;
}
