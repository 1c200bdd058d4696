#pragma once

#include "MessageText.h"
#include "Settings.h"

#include <QCommandLineParser>
#include <QSize>
#include <QString>
#include <QStringList>

#include <stdexcept>

// The settings a command line describes, shared by every command and by the fuzz target of
// settings files: the options, their reading into Settings, and sizes and counts.
namespace shadowlab {

// Bad command-line input that is not a setting (a malformed --size, a missing option).
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const QString& message) : std::runtime_error(escapeControlCharacters(message).toStdString()) {}
};

// Adds --scene, --set (repeatable), --settings, --preset, --import-time-limit and
// --import-memory-limit to `parser`.
void addSettingsOptions(QCommandLineParser& parser);
void addImportOptions(QCommandLineParser& parser);  // --import-time-limit, --import-memory-limit
// The import limits those options give, made the process's (ImportLimits.h); throws
// SettingsError naming the option. settingsFromOptions() calls it first.
void applyImportOptions(const QCommandLineParser& parser);


// The settings those options describe: the scene's preset (from --set scene=..., --scene, the
// file's "scene", the artifact preset's scene, or "seed", in that order), then the artifact
// preset's keys, then the JSON file, then every --set in order. Throws SettingsError; the
// warnings of validate() and of a scene file come back for the caller to show.
struct SettingsFromOptions {
    Settings settings;
    QStringList warnings;   // "key: message"
};
SettingsFromOptions readSettingsOptions(const QCommandLineParser& parser);

// "1280x720" -> QSize within [minimum, maximum] (each side); throws UsageError naming the
// option, the command's limits and what they are for.
struct SizeLimits {
    QSize minimum{1, 1};
    QSize maximum;
    QString reason;     // why the maximum, e.g. "report keeps ~90 bytes per pixel in memory"
};
QSize parseSize(const QString& text, const QString& option, const SizeLimits& limits);
int parseCount(const QString& text, const QString& option, int minimum, int maximum);

} // namespace shadowlab
