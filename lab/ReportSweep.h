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
// widths, both formats, with and without bleeding reduction), "virtual" (virtual shadow maps against
// a map and cascades of the same memory), "cache" (shadow.cache's policies, for report --animation),
// "around" (sweepAround()); or a JSON file: an array of {"label": ..., "set": {key: value}}
// objects (or {"configurations": [...]}). Throws SettingsError with the file named.
// The file is read once, within readInputFile()'s limits; every entry must be an object with
// only "label" (a string) and "set" (an object of setting values).
// "around" is sweepAround(base).
std::vector<SweepEntry> loadSweep(const QString& nameOrFile, const Settings& base = Settings());
QStringList builtInSweeps();

// The accuracy dock's sweep, and `report --sweep around`: the base settings first, then one
// change at a time: each filter and the variations its row of the technique table lists, half
// and double the map, bias halved, doubled and off; front-face culling, contact shadows, sdsm
// (with cascades) and cut-out masks (in a scene with cut-outs) toggled. Changes that make
// `base` invalid or repeat an earlier configuration are left out.
std::vector<SweepEntry> sweepAround(const Settings& base);

// The sweep a file's bytes describe, checked as loadSweep() does; `path` names it in errors.
std::vector<SweepEntry> parseSweepFile(const QByteArray& bytes, const QString& path);

// The settings of one entry; throws SettingsError prefixed with the entry's label.
Settings applySweepEntry(const Settings& base, const SweepEntry& entry);

// One configuration to measure: entries whose settings come out the same on `base` (the
// defaults and "no front-face culling" on open casters, say) are measured once, their labels
// joined with " = ".
struct SweepConfiguration {
    QString label;
    QStringList assignments;    // of the first entry
    Settings settings;
};
// Throws SettingsError as applySweepEntry() does; keeps the order of first appearance.
std::vector<SweepConfiguration> distinctConfigurations(const Settings& base, const std::vector<SweepEntry>& sweep);

// The classic tutorial configuration (3 x 3 PCF on a 1024 map, bias 0.05/0.005 in depth
// units, front faces drawn, the hand-set volume) as assignments.
QStringList tutorialAssignments();

} // namespace shadowlab
