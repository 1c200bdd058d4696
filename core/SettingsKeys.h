#pragma once

#include "Settings.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// The dotted keys shared by `--set key=value`, JSON files and the GUI.
// How the properties dock shows a key: its row's label, the unit after its value, the decimals
// shown, the part of its range worth a slider (logarithmic for sizes), and its group.
struct SettingPresentation {
    QString label{};
    QString unit{};
    int decimals = 0;
    double sliderLow = 0.0;
    double sliderHigh = 0.0;
    bool logarithmic = false;
    QString group{};        // one of settingGroups()
};

struct SettingKey {
    QString key;            // "bias.slope"
    QString type;           // "number", "integer", "bool", "vec3", "choice"
    QString range;          // "[0, 0.5]", "ortho | perspective", ...
    QString help;           // one line: what it does and what it trades against
    QStringList choices;    // for "choice"
    double minimum = 0.0;   // for numbers and integers: the slider range
    double maximum = 0.0;
    SettingPresentation presentation;
};

const std::vector<SettingKey>& settingKeys();
// The groups of the dock, in order.
const QStringList& settingGroups();
const SettingKey* findSettingKey(const QString& key);

// The value of `key` in `settings`, formatted as it would be typed on the command line.
QString settingValue(const Settings& settings, const QString& key);

// Parses `value` for `key` and stores it in `settings`. Throws SettingsError naming the key
// and the allowed range when the key is unknown or the value does not parse or is out of
// range; `settings` is left unchanged then. Cross-field rules (near < far, ...) are
// validate()'s job.
void applySetting(Settings& settings, const QString& key, const QString& value);

// Applies "key=value"; throws SettingsError when there is no '='.
void applyAssignment(Settings& settings, const QString& assignment);

// Flat object of dotted keys to values, in key order.
QJsonObject settingsToJson(const Settings& settings);

// A JSON object (flat dotted keys, or nested objects that spell the same keys) as "key=value"
// assignments; throws SettingsError naming the key for a value that is not a number, string,
// boolean or array of numbers. Keys and values are checked when applied.
QStringList assignmentsFromJson(const QJsonObject& object);

// Applies a JSON object (flat dotted keys, or nested objects that spell the same keys) on
// top of `base`. Throws SettingsError for unknown keys, wrong types or values out of range.
Settings settingsFromJson(const QJsonObject& object, const Settings& base);

// Reads a JSON settings file once (pipes work; see readInputFile() for the limits); throws
// SettingsError naming the file when it is missing, too big, malformed or not an object.
QJsonObject readSettingsObject(const QString& path);
// settingsFromJson() with errors that name the file.
Settings settingsFromFileObject(const QString& path, const QJsonObject& object, const Settings& base);
// Both of the above.
Settings loadSettingsFile(const QString& path, const Settings& base);
// Writes the file whole or not at all; throws OutputError (see OutputFile.h).
void saveSettingsFile(const QString& path, const Settings& settings);

QString toString(LightProjection value);
QString toString(LightType value);
QString toString(CascadeSplit value);
QString toString(DepthFit value);
QString toString(LightWarp value);
QString toString(LightFit value);
QString toString(DepthFormat value);
QString toString(BiasSpace value);
QString toString(FilterMode value);
QString toString(ShadingModel value);
QString toString(RasteriserProfile value);
QString toString(ShadowCachePolicy value);
QString toString(MomentFormat value);
QString toString(MomentBlurAt value);

} // namespace shadowlab
