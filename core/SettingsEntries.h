#pragma once

// Inside the settings schema, shared by its table (SettingsTable.cpp), its parsing
// (SettingsParsing.cpp), its JSON (SettingsJson.cpp) and its validation (SettingsValidation.cpp).
// Outside core, SettingsKeys.h is the interface.

#include "SettingsKeys.h"

#include <QString>

#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace shadowlab::settings {

// Coordinates beyond this are refused: far past any scene, and still exact in float.
inline constexpr double kMaxCoordinate = 1e7;

// A number's allowed interval, each end closed unless marked open.
struct Range {
    double lo = 0.0;
    double hi = 0.0;
    bool loOpen = false;
    bool hiOpen = false;

    bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
    QString text() const;    // "[0, 1]", "(0, 1e+06]"
};

// One key: what it is, and how to read, write and check its value in Settings.
struct Entry {
    SettingKey info;
    std::function<QString(const Settings&)> get;
    std::function<void(Settings&, const QString&)> set;         // throws SettingsError naming the key
    std::function<std::optional<QString>(const Settings&)> check;
};

// Every key, in the order `shadowlab settings`, JSON files and the dock list them.
const std::vector<Entry>& entries();
// The entry of `key`; a SettingsError that suggests the nearest key when there is none.
const Entry& entryFor(const QString& key);

// Values as text, the way files and the command line write them.
QString formatNumber(double v);
QString formatVec3(const glm::dvec3& v);

// Why a value is out of its range, or nothing when it is in it.
std::optional<QString> checkNumber(double v, const Range& range);
std::optional<QString> checkVec3(const glm::dvec3& v);

// Text to values; each throws a SettingsError naming `key`, what is wrong and what is allowed.
double parseNumber(const QString& key, const QString& text, const Range& range);
int parseWholeNumber(const QString& key, const QString& text, const QString& allowed);
bool parseBool(const QString& key, const QString& text);
glm::dvec3 parseVec3(const QString& key, const QString& text);

} // namespace shadowlab::settings
