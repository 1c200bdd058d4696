#pragma once

#include "Settings.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// One configuration of a report: a label and the settings it changes from the base.
struct SweepEntry {
    QString label;
    QStringList assignments;    // "key=value", applied on top of the base settings
};

// The built-in sweeps: "default" (all of the below, plus the classic tutorial configuration),
// "filters", "resolution", "bias", "lights"; or a JSON file: an array of {"label": ..., "set": {key: value}}
// objects (or {"configurations": [...]}). Throws SettingsError naming the
// file when it cannot be read or does not hold settings (like a settings file).
std::vector<SweepEntry> loadSweep(const QString& nameOrFile);
QStringList builtInSweeps();

// The settings of one entry; throws SettingsError prefixed with the entry's label.
Settings applySweepEntry(const Settings& base, const SweepEntry& entry);

} // namespace shadowlab
