#include "CliSupport.h"
#include "Commands.h"
#include "MessageText.h"

#include <QFileInfo>

namespace shadowlab::cli {

namespace {

struct Command {
    const char* name;
    const char* summary;
    int (*run)(const QStringList&);
    bool widgets = false;
};

const Command kCommands[] = {
    {"render", "Render the scene (and optionally the shadow map) headless to PNG", runRender},
    {"bench", "Time the shadow and lit passes over many frames", runBench},
    {"report", "Error against run time over a sweep, against a ray-traced reference", runReport},
    {"settings", "List every setting with its default and range", runSettings},
    {"audit", "Run the extreme and degenerate cases and print pass/fail for each", runAudit},
    {"tune", "Search the bias that misclassifies the fewest pixels, over several light directions", runTune},
    {"screenshot", "Save the explorer window, rendered offscreen, as PNG", runScreenshot, true},
};

} // namespace

bool isCommand(const QString& name)
{
    for (const Command& c : kCommands) {
        if (name == QLatin1String(c.name))
            return true;
    }
    return false;
}

bool needsWidgets(const QString& name)
{
    for (const Command& c : kCommands) {
        if (name == QLatin1String(c.name))
            return c.widgets;
    }
    return false;
}

QStringList commandNames()
{
    QStringList names;
    for (const Command& c : kCommands)
        names << QString::fromLatin1(c.name);
    return names;
}

int runCommand(const QStringList& arguments)
{
    for (const Command& c : kCommands) {
        if (arguments.value(0) == QLatin1String(c.name))
            return c.run(arguments.mid(1));
    }
    printUsage(err());
    return kExitBadInput;
}

bool isMistypedCommand(const QStringList& arguments)
{
    if (arguments.isEmpty())
        return false;
    const QString& word = arguments.first();
    return !word.startsWith(QLatin1Char('-')) && !isCommand(word) && !QFileInfo::exists(word) && !word.contains(QLatin1Char('/'))
           && !word.contains(QLatin1Char('.'));
}

int unknownCommand(const QString& name)
{
    const QString match = closestMatch(name, commandNames());
    err() << "shadowlab: '" << displayText(name) << "' is not a command"
          << (match.isEmpty() ? QString() : QStringLiteral("; did you mean '%1'?").arg(match)) << "\n\n";
    printUsage(err());
    return kExitBadInput;
}

void printUsage(QTextStream& stream)
{
    stream << "usage: shadowlab [command] [options]\n"
           << "       shadowlab [file] [--scene name|file] [--preset name] [--settings file.json] [--set key=value ...]\n\n"
           << "With no command, opens the explorer window; settings options start side A from them (as every command\n"
           << "takes them), and a model or scene file alone opens it.\n\nCommands:\n";
    for (const Command& c : kCommands)
        stream << "  " << QString::fromLatin1(c.name).leftJustified(12) << c.summary << '\n';
    stream << "\nOptions:\n"
           << "  -h, --help    Print this help (`shadowlab help <command>` or `shadowlab <command> --help` for a command's options).\n"
           << "  -v, --version Print the version.\n"
           << "\nRun `shadowlab <command> --help` for a command's options." << Qt::endl;
}

} // namespace shadowlab::cli
