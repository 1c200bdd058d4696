#pragma once

#include <QStringList>
#include <QTextStream>

namespace shadowlab::cli {

// Each takes the arguments after the subcommand's name and returns the process exit code.
int runRender(const QStringList& arguments);
int runBench(const QStringList& arguments);
int runReport(const QStringList& arguments);
int runSettings(const QStringList& arguments);
int runAudit(const QStringList& arguments);
int runTune(const QStringList& arguments);
int runScreenshot(const QStringList& arguments);  // needs a QApplication
// The explorer window, side A on the settings options when given (`shadowlab --preset acne`,
// `shadowlab model.glb`); needs a QApplication and a display.
int runExplorer(const QStringList& arguments);

// True when `name` is a subcommand; runCommand dispatches to it (`args[0]` is the name).
bool isCommand(const QString& name);
// True when the subcommand builds widgets and so needs a QApplication, not a QGuiApplication.
bool needsWidgets(const QString& name);
int runCommand(const QStringList& arguments);
QStringList commandNames();
// The binary's usage (commands and their summaries) on `stream`: stdout when asked for,
// stderr after a mistake.
void printUsage(QTextStream& stream);
// True when the first argument is a word that is no command, no option and no file, nor looks
// like a path: a mistyped command, whatever follows it (`rendr --scene seed` names no model).
bool isMistypedCommand(const QStringList& arguments);
// Says `name` is no command (suggesting the nearest one) with the usage on stderr; returns 2.
int unknownCommand(const QString& name);

} // namespace shadowlab::cli
