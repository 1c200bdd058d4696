#pragma once

#include <QByteArray>
#include <QString>

#include <stdexcept>


namespace shadowlab {

// A file that cannot be written. BadLocation is found before any work (a missing or read-only
// folder, a path that is a folder or a device): the user's to fix, exit code 2. WriteFailed
// happens while writing (disk full, I/O error): exit code 1. Either way nothing was
// written at the path and an existing file there is untouched.
class OutputError : public std::runtime_error {
public:
    enum class Kind { BadLocation, WriteFailed };
    OutputError(Kind kind, const QString& message) : std::runtime_error(message.toStdString()), m_kind(kind) {}
    Kind kind() const { return m_kind; }

private:
    Kind m_kind;
};

// Checks, writing nothing, that `path` can be written: its folder exists and accepts new
// files, and the path is not a folder, a device or a pipe. Throws OutputError(BadLocation)
// naming `what` (e.g. "--out") and the path.
void checkOutputFile(const QString& path, const QString& what);

// The same for a folder that will receive files; it may not exist yet if its nearest
// existing parent accepts new folders.
void checkOutputFolder(const QString& path, const QString& what);

// Writes `bytes` whole or not at all: into a temporary file in the same folder, renamed over
// `path` only once everything is on disk. Throws OutputError(WriteFailed) otherwise, and then
// an existing file at `path` is untouched and no temporary file is left.
void writeOutputFile(const QString& path, const QByteArray& bytes);

} // namespace shadowlab
