#pragma once

#include "Scene.h"
#include "SceneNames.h"
#include "Settings.h"

#include <QStringList>

namespace shadowlab {

// Builds a preset's geometry, or loads the model or scene file `name` is a path of
// (SceneLoader.h); throws SettingsError (SceneFileError for files) when it cannot.
Scene buildScene(const QString& name);

// Default settings for a preset (the global defaults with the preset's light and camera) or
// for a model or scene file (derived from its bounds, then the file's own keys).
Settings presetSettings(const QString& name);

// What a scene's references may be cached under: a preset's name, or "sha256:" and the hash
// of a loaded file's content (and of the files it names), so renaming a file keeps its cached
// traces and editing it does not. Throws like buildScene().
QString sceneIdentity(const QString& name);

} // namespace shadowlab
