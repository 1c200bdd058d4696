#include "ModelFileChecks.h"

#include "Limits.h"
#include "ModelImporter.h"
#include "SceneFileError.h"

#include <QFile>

namespace shadowlab {

namespace {

// OFF and PLY headers say how many vertices and faces follow, and Assimp reserves memory for
// them before reading one: a damaged count (the classic "OutOfMemory.off" declares over a
// billion vertices in 309 bytes) would take gigabytes and minutes. Every element takes at least
// one byte of the file, so a count larger than the file is refused before Assimp sees it.
// Returns what is wrong, or an empty string.
QString declaredCountProblem(const QString& path, const QString& suffix, qint64 size)
{
    if (suffix != u"off" && suffix != u"ply")
        return QString();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QString();
    const QByteArray head = file.read(64 * 1024);
    const QList<QByteArray> lines = head.split('\n');
    const auto tooMany = [&](const QByteArray& what, const QByteArray& count) {
        bool ok = false;
        const qulonglong n = count.trimmed().toULongLong(&ok);
        return ok && n > qulonglong(size) ? QStringLiteral("declares %1 %2 in a file of %3 bytes; the header is damaged — export the model again")
                                                 .arg(QString::fromLatin1(count.trimmed()), QString::fromLatin1(what))
                                                 .arg(size)
                                           : QString();
    };
    if (suffix == u"off") {
        // "OFF" (or COFF, NOFF, ...) then "vertices faces edges", skipping comments and blank lines.
        bool keyword = false;
        for (const QByteArray& raw : lines) {
            const QByteArray line = raw.simplified();
            if (line.isEmpty() || line.startsWith('#'))
                continue;
            QList<QByteArray> fields = line.split(' ');
            if (!keyword && fields.first().endsWith("OFF")) {
                keyword = true;
                fields.removeFirst();       // the counts may follow on the same line
                if (fields.isEmpty())
                    continue;
            }
            if (fields.size() >= 2) {
                if (QString problem = tooMany("vertices", fields[0]); !problem.isEmpty())
                    return problem;
                return tooMany("faces", fields[1]);
            }
            return QString();
        }
        return QString();
    }
    for (const QByteArray& raw : lines) {   // ply: "element <name> <count>" up to end_header
        const QByteArray line = raw.simplified();
        if (line == "end_header")
            break;
        const QList<QByteArray> fields = line.split(' ');
        if (fields.size() == 3 && fields[0] == "element") {
            if (QString problem = tooMany(fields[1] + "s", fields[2]); !problem.isEmpty())
                return problem;
        }
    }
    return QString();
}

} // namespace

// Refuses what is no model file, before Assimp opens it; returns its suffix in lower case.
QString checkModelFile(const QString& path, const QFileInfo& info)
{
    if (!info.exists())
        throw SceneFileError(path, QStringLiteral("no such file; check the path"));
    if (!info.isFile() || !info.isReadable())
        throw SceneFileError(path, QStringLiteral("is not a readable file; check its permissions"));
    if (info.size() > kMaxModelFileBytes)
        throw SceneFileError(path, QStringLiteral("is %1 MiB, larger than the %2 MiB ShadowLab reads; decimate or split the model")
                                       .arg(info.size() >> 20).arg(kMaxModelFileBytes >> 20));
    if (info.size() == 0)
        throw SceneFileError(path, QStringLiteral("is empty (0 bytes); the export or copy did not finish"));
    const QString suffix = info.suffix().toLower();
    if (!modelSuffixes().contains(suffix))
        throw SceneFileError(path, QStringLiteral("'.%1' is not a model format ShadowLab reads; use glTF 2 (.gltf, .glb), OBJ, PLY, STL, "
                                                  "COLLADA (.dae) or FBX, or a scene file (.json)").arg(suffix));
    if (const QString problem = declaredCountProblem(info.absoluteFilePath(), suffix, info.size()); !problem.isEmpty())
        throw SceneFileError(path, problem);
    return suffix;
}

} // namespace shadowlab
