#pragma once

#include "LightFitting.h"

#include "FrameStats.h"
#include "Settings.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QSize>
#include <QStringList>
#include <QTextStream>

#include <functional>
#include <stdexcept>

namespace shadowlab::cli {

// Exit codes of every subcommand.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;     // the program failed (driver, I/O)
constexpr int kExitBadInput = 2;    // the user asked for something impossible; nothing was done

// Bad command-line input that is not a setting (a malformed --size, a missing option).
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

QTextStream& out();
QTextStream& err();

// Parses `arguments` (those after the command's name); throws UsageError for unknown options
// or stray positional arguments. Returns false when --help was asked for and printed.
bool parseArguments(QCommandLineParser& parser, const QString& command, const QStringList& arguments);

// Adds --scene, --set (repeatable) and --settings to `parser`.
void addSettingsOptions(QCommandLineParser& parser);

// The settings those options describe: the scene's preset (from --set scene=..., --scene, the
// file's "scene", or "seed", in that order), then the JSON file, then every --set in order.
// Throws SettingsError; warnings of validate() are printed to stderr.
Settings settingsFromOptions(const QCommandLineParser& parser);

// "shadow texel: 0.0195 world units as set, 0.0132 fitted (light.fit=scene)": what fitting bought.
QString formatTexelLine(const FrameStats& stats);
// The light fit's warnings (receivers a manual volume cuts, ...) on stderr, after `context`.
void printFitWarnings(const FittedLight& fit, const QString& context = {});

// "1280x720" -> QSize; throws UsageError naming the option.
QSize parseSize(const QString& text, const QString& option);
int parseCount(const QString& text, const QString& option, int minimum, int maximum);

// Runs `body`, turning SettingsError / UsageError into exit code 2 and RenderError into 1,
// with the message on stderr.
// A one-line progress bar with the time left, redrawn in place on stderr; only on a terminal.
class ProgressBar {
public:
    ProgressBar();
    void show(double fraction, const QString& what);
    void done();

private:
    bool m_enabled;
    QElapsedTimer m_timer;
};

int guarded(const QString& command, const std::function<int()>& body);

} // namespace shadowlab::cli
