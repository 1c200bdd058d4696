#pragma once

#include "Settings.h"

#include <QByteArray>
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
// "filters", "resolution", "bias", "lights", "filterable" (the moment techniques over blur
// widths, both formats, with and without bleeding reduction); or a JSON file: an array of {"label": ..., "set": {key: value}}
// objects (or {"configurations": [...]}). Throws SettingsError with the file named.
// The file is read once, within readInputFile()'s limits; every entry must be an object with
// only "label" (a string) and "set" (an object of setting values).
std::vector<SweepEntry> loadSweep(const QString& nameOrFile);
QStringList builtInSweeps();

// The sweep a file's bytes describe, checked as loadSweep() does; `path` names it in errors.
std::vector<SweepEntry> parseSweepFile(const QByteArray& bytes, const QString& path);

// The settings of one entry; throws SettingsError prefixed with the entry's label.
Settings applySweepEntry(const Settings& base, const SweepEntry& entry);

} // namespace shadowlab
