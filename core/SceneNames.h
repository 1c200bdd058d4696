#pragma once

#include <QStringList>

namespace shadowlab {

// The built-in scene presets, by name: the values of the `scene` key. The scene library builds
// each (buildScene(), presetSettings()); tst_Scene checks that every name builds.
const QStringList& sceneNames();

} // namespace shadowlab
