#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

// Files the tests make: models, damaged files and stand-ins for the import worker.
inline const QString kTestModels = QStringLiteral("/usr/share/assimp/models/");    // Debian's assimp-testmodels

// Writes `bytes` to `name` in `dir` and returns its path; a test cannot go on without it.
inline QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}
