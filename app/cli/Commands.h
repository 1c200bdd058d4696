#pragma once

#include <QStringList>

namespace shadowlab::cli {

// Each takes the arguments after the subcommand's name and returns the process exit code.
int runRender(const QStringList& arguments);
int runBench(const QStringList& arguments);
int runSettings(const QStringList& arguments);

// True when `name` is a subcommand; runCommand dispatches to it (`args[0]` is the name).
bool isCommand(const QString& name);
int runCommand(const QStringList& arguments);
void printUsage();

} // namespace shadowlab::cli
