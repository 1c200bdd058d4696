#pragma once

#include "Settings.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// A shadow artifact made visible in one click: a settings file shipped as a resource
// (resources/presets/<name>.json) whose dotted keys reproduce the artifact on top of its scene's
// defaults, with a sentence on what to look for and which setting fixes it. The "preset" object
// of the file holds the sentences and the fix as keys; everything else is ordinary settings, so
// adding a preset is adding a file.
struct ArtifactPreset {
    QString name;               // "acne": the file's name, what --preset takes
    QString title;              // "Shadow acne"
    QString lookFor;            // what the artifact looks like on screen
    QString fix;                // which setting removes it, in words
    QJsonObject settings;       // the keys the preset sets ("scene" included)
    QJsonObject fixSettings;    // the keys of the fix, applied on top of the preset
    int order = 0;              // place in menus and lists
};

// Every shipped preset, in display order; read once from the resources.
const std::vector<ArtifactPreset>& artifactPresets();
QStringList artifactPresetNames();
// The preset called `name`; throws SettingsError (key "preset") listing the names otherwise.
const ArtifactPreset& artifactPreset(const QString& name);

// The preset on top of `base`, whose scene it keeps unless the preset names one (then the
// scene's defaults are the base, camera included). Throws SettingsError.
Settings applyArtifactPreset(const ArtifactPreset& preset, const Settings& base);
// The preset on its own scene's defaults, and the same with its fix applied.
Settings artifactPresetSettings(const ArtifactPreset& preset);
Settings artifactPresetFixed(const ArtifactPreset& preset);

} // namespace shadowlab
