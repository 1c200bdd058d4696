// shadowlab-import-worker FILE: reads one model file with Assimp (importModel) and writes the
// scene, or why it cannot be read, to standard output (ImportPayload.h); progress lines
// ("progress 0.42") go to standard error. The explorer and the command line start it through
// importModelIsolated(), under limits, so that a damaged file can crash or hang this process
// and nothing else.
#include "ImportPayload.h"
#include "ModelImporter.h"
#include "SceneFileError.h"

#include <QCoreApplication>
#include <QFile>

#include <cmath>
#include <cstdio>
#include <new>

using namespace shadowlab;

namespace {

bool writeAll(const QByteArray& bytes)
{
    QFile out;
    if (!out.open(stdout, QIODevice::WriteOnly | QIODevice::Unbuffered))
        return false;
    return out.write(bytes) == bytes.size();
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);   // Qt's image plugins, for textures
    const QStringList arguments = app.arguments();
    if (arguments.size() != 2) {
        std::fputs("usage: shadowlab-import-worker FILE (started by shadowlab, not by hand)\n", stderr);
        return 64;
    }
    const QString path = arguments.at(1);
    double reported = -1.0;
    const auto progress = [&reported](double fraction) {
        if (std::abs(fraction - reported) >= 0.01) {
            reported = fraction;
            std::fprintf(stderr, "progress %.3f\n", fraction);
            std::fflush(stderr);
        }
    };
    QByteArray answer;
    try {
        answer = encodeImportedScene(importModel(path, progress));
    } catch (const SceneFileError& e) {
        // Assimp turns an allocation it could not make into an error string.
        const ImportReplyKind kind = e.problem().contains(QStringLiteral("bad_alloc")) ? ImportReplyKind::OutOfMemory : ImportReplyKind::Refusal;
        answer = encodeImportRefusal(kind, kind == ImportReplyKind::Refusal ? e.problem() : QStringLiteral("an allocation failed"));
    } catch (const std::bad_alloc&) {
        answer = encodeImportRefusal(ImportReplyKind::OutOfMemory, QStringLiteral("an allocation failed"));
    }
    progress(1.0);
    return writeAll(answer) ? 0 : 74;
}
