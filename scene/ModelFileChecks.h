#pragma once

#include <QFileInfo>
#include <QString>

namespace shadowlab {

// Refuses what is no model file before Assimp opens it, with a SceneFileError that says what is
// wrong and what to do: missing, unreadable, empty, too large, not a model format, or an OFF or
// PLY header that declares more elements than the file has bytes. Returns the suffix in lower case.
QString checkModelFile(const QString& path, const QFileInfo& info);

} // namespace shadowlab
