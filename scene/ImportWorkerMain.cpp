// shadowlab-import-worker FILE [--answer-fd N]: reads one model file with Assimp (importModel)
// and writes the scene, or why it cannot be read (ImportPayload.h), to file descriptor N, or to
// standard output; progress lines ("progress 0.42") go to standard error. The explorer and the command line start it through
// importModelIsolated(), under limits, so that a damaged file can crash or hang this process
// and nothing else.
#include "ImportPayload.h"
#include "ModelImporter.h"
#include "SceneFileError.h"

#include <QCoreApplication>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <new>

#include <unistd.h>

using namespace shadowlab;

namespace {

bool writeAll(int fd, const QByteArray& bytes)
{
    const char* data = bytes.constData();
    std::size_t left = std::size_t(bytes.size());
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0)
            return false;
        data += written;
        left -= std::size_t(written);
    }
    return true;
}

} // namespace

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);   // Qt's image plugins, for textures
    const QStringList arguments = app.arguments();
    int fd = STDOUT_FILENO;
    bool ok = arguments.size() == 2;
    if (arguments.size() == 4 && arguments.at(2) == u"--answer-fd")
        fd = arguments.at(3).toInt(&ok);
    if (!ok) {
        std::fputs("usage: shadowlab-import-worker FILE [--answer-fd N] (started by shadowlab, not by hand)\n", stderr);
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
    return writeAll(fd, answer) ? 0 : 74;
}
