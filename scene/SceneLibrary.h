#pragma once

#include "Scene.h"
#include "SceneNames.h"
#include "Settings.h"

#include <QStringList>

namespace shadowlab {

// Builds a preset's geometry; throws SettingsError for an unknown name.
Scene buildScene(const QString& name);

// Default settings for a preset: the global defaults with the preset's light and camera.
Settings presetSettings(const QString& name);

} // namespace shadowlab
