#pragma once

#include "LightFitting.h"
#include "SettingsOptions.h"

#include "FrameStats.h"
#include "MessageText.h"
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
constexpr int kExitFailure = 1;     // the program failed (driver, or I/O while writing: the old file is kept)
constexpr int kExitBadInput = 2;    // the user asked for something impossible (including an output path that
                                    // cannot be written, found before any work); nothing was done

QTextStream& out();
QTextStream& err();

// Parses `arguments` (those after the command's name); throws UsageError for unknown options
// (suggesting the nearest known one), options given twice (all but --set and --set-b) or stray
// positional arguments (unless `positional`, where the command reads them). Adds -v/--version.
// Returns false when --help or --version was asked for and printed on stdout.
bool parseArguments(QCommandLineParser& parser, const QString& command, const QStringList& arguments, bool positional = false);
// The parser's help with its usage line naming `shadowlab <command>`, not the binary's path.
QString commandHelp(const QCommandLineParser& parser, const QString& command);

// readSettingsOptions() (SettingsOptions.h) with its warnings printed on stderr.
Settings settingsFromOptions(const QCommandLineParser& parser);

// "shadow texel: 0.0195 world units as set, 0.0132 fitted (light.fit=scene)": what fitting bought.
QString formatTexelLine(const FrameStats& stats);
// The light fit's warnings (receivers a manual volume cuts, ...) on stderr, after `context`.
void printFitWarnings(const FittedLight& fit, const QString& context = {});

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

// Runs `body`, turning SettingsError / UsageError / OutputError(BadLocation) into exit code 2
// and RenderError / OutputError(WriteFailed) into 1, with the message on stderr.
int guarded(const QString& command, const std::function<int()>& body);

} // namespace shadowlab::cli
