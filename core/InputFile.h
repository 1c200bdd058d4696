#pragma once

#include <QByteArray>
#include <QString>

namespace shadowlab {

// The most a settings or sweep file may hold: far above any real one (a few kB), far
// below what would strain memory.
constexpr qint64 kMaxInputFileBytes = 1 << 20;
// How long a pipe or FIFO may stay silent before reading gives up.
constexpr int kInputWaitMs = 5000;

// Reads a whole input file once, so pipes (`<(echo ...)`, /dev/stdin) work. Refuses, with
// a SettingsError naming `what` and the path, a folder, a file over kMaxInputFileBytes
// (checked while reading, so /dev/zero fails fast) and a pipe or FIFO that stays silent
// for kInputWaitMs (no writer).
QByteArray readInputFile(const QString& path, const QString& what);

} // namespace shadowlab
