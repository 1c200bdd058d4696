#include "OutputFile.h"

#include "MessageText.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryFile>

#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace shadowlab {

namespace {

OutputError badLocation(const QString& what, const QString& path, const QString& reason)
{
    return OutputError(OutputError::Kind::BadLocation, QStringLiteral("%1: cannot write '%2': %3").arg(what, displayText(path), reason));
}

// Creating (and at once removing) a file is the only sure test: permissions say nothing
// about read-only mounts or /proc, and root passes every permission check.
QString folderProblem(const QString& folder)
{
    const QFileInfo info(folder);
    if (!info.exists())
        return QStringLiteral("the folder '%1' does not exist").arg(displayText(folder));
    if (!info.isDir())
        return QStringLiteral("'%1' is not a folder").arg(displayText(folder));
    QTemporaryFile probe(QDir(folder).filePath(QStringLiteral(".shadowlab-probe-XXXXXX")));
    if (!probe.open())
        return QStringLiteral("the folder '%1' does not accept new files (%2)").arg(displayText(folder), probe.errorString());
    return QString();
}

} // namespace

void checkOutputFile(const QString& path, const QString& what)
{
    if (path.isEmpty())
        throw OutputError(OutputError::Kind::BadLocation, QStringLiteral("%1: give a file name").arg(what));
    const QFileInfo info(path);
    if (info.exists() && info.isDir())
        throw badLocation(what, path, QStringLiteral("it is a folder; give a file name in it"));
    if (info.exists() && !info.isFile())
        throw badLocation(what, path, QStringLiteral("it is a device, pipe or socket, not a file; give a file name in a folder"));
    if (info.exists() && !info.isWritable())
        throw badLocation(what, path, QStringLiteral("the file is read-only"));
    if (const QString problem = folderProblem(info.absolutePath()); !problem.isEmpty())
        throw badLocation(what, path, problem);
}

void checkOutputFolder(const QString& path, const QString& what)
{
    if (path.isEmpty())
        throw OutputError(OutputError::Kind::BadLocation, QStringLiteral("%1: give a folder name").arg(what));
    QFileInfo info(path);
    if (info.exists()) {
        if (const QString problem = folderProblem(info.absoluteFilePath()); !problem.isEmpty())
            throw badLocation(what, path, problem);
        return;
    }
    // The nearest existing parent must let the missing folders be created. (QDir::cdUp() does
    // not leave a folder that does not exist, so the path is walked up by its text.)
    QString parent = QDir::cleanPath(info.absoluteFilePath());
    while (!QFileInfo::exists(parent) && parent != QDir::rootPath())
        parent = QFileInfo(parent).absolutePath();
    if (const QString problem = folderProblem(parent); !problem.isEmpty())
        throw badLocation(what, path, problem);
}

void writeOutputFile(const QString& path, const QByteArray& bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("cannot write '%1': %2").arg(displayText(path), file.errorString()));
    // Written with write(2) and synced here rather than through QIODevice: its buffered writes
    // lose a short write (a full disk, a file size limit) without an error.
    const int fd = file.handle();
    qsizetype done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.constData() + done, std::size_t(bytes.size() - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        done += n;
    }
    const QString reason = done < bytes.size() ? QString::fromLocal8Bit(std::strerror(errno))
                         : ::fsync(fd) != 0    ? QString::fromLocal8Bit(std::strerror(errno))
                                               : QString();
    if (!reason.isEmpty()) {
        file.cancelWriting();
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("writing '%1' failed after %2 of %3 bytes, so it was left as it was: %4")
                                                              .arg(displayText(path))
                                                              .arg(done)
                                                              .arg(bytes.size())
                                                              .arg(reason));
    }
    if (!file.commit())
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("writing '%1' failed, so it was left as it was: %2")
                                                              .arg(displayText(path), file.errorString()));
}

} // namespace shadowlab
