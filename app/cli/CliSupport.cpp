#include "CliSupport.h"

#include "Application.h"
#include "IoError.h"
#include "OutputFile.h"
#include "ImportLimits.h"
#include "RenderError.h"
#include "SceneFileError.h"
#include "SettingsError.h"
#include "TraceError.h"

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>

#include <unistd.h>

namespace shadowlab::cli {

QTextStream& out()
{
    static QTextStream stream(stdout);
    return stream;
}

QTextStream& err()
{
    static QTextStream stream(stderr);
    return stream;
}

namespace {

// The long option names `parser` knows, read from its help (QCommandLineParser lists them
// nowhere else).
QStringList optionNames(const QCommandLineParser& parser)
{
    QStringList names;
    static const QRegularExpression option(QStringLiteral("--([a-z0-9][a-z0-9-]*)"));
    for (auto it = option.globalMatch(parser.helpText()); it.hasNext();)
        names << it.next().captured(1);
    names.removeDuplicates();
    return names;
}

} // namespace

QString commandHelp(const QCommandLineParser& parser, const QString& command)
{
    // Qt names the binary as it was started (often a full path); the user types the command.
    QString text = parser.helpText();
    const qsizetype end = text.indexOf(QLatin1Char('\n'));
    QString first = text.left(end);
    const QString program = QCoreApplication::arguments().value(0);
    if (!program.isEmpty() && first.contains(program))
        first.replace(first.indexOf(program), program.size(), command.isEmpty() ? QStringLiteral("shadowlab") : QStringLiteral("shadowlab ") + command);
    return first + text.mid(end);
}

bool parseArguments(QCommandLineParser& parser, const QString& command, const QStringList& arguments, bool positional)
{
    const QCommandLineOption version({QStringLiteral("v"), QStringLiteral("version")}, QStringLiteral("Print the version and exit."));
    parser.addOption(version);
    // The explorer itself has no command name.
    const QString invocation = command.isEmpty() ? QStringLiteral("shadowlab") : QStringLiteral("shadowlab ") + command;
    if (!parser.parse(QStringList{invocation} + arguments)) {
        QString message = parser.errorText();
        if (const QStringList unknown = parser.unknownOptionNames(); !unknown.isEmpty()) {
            if (const QString match = closestMatch(unknown.first(), optionNames(parser)); !match.isEmpty())
                message += QStringLiteral(" Did you mean --%1?").arg(match);
        }
        throw UsageError(message + QStringLiteral(" Run `%1 --help` for its options.").arg(invocation));
    }
    // --help-all (which Qt adds with --help) would list Qt's own options, none of which a
    // command takes: the same help.
    if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("help-all"))) {
        out() << commandHelp(parser, command) << Qt::flush;
        return false;
    }
    if (parser.isSet(version)) {
        out() << versionText() << Qt::flush;
        return false;
    }
    if (!positional && !parser.positionalArguments().isEmpty())
        throw UsageError(QStringLiteral("unexpected argument '%1'; run `%2 --help`").arg(displayText(parser.positionalArguments().first()), invocation));
    // QCommandLineParser keeps the last of a repeated option; a user who wrote two meant something.
    const QStringList given = parser.optionNames();
    for (const QString& name : given) {
        if (name != u"set" && name != u"set-b" && given.count(name) > 1)
            throw UsageError(QStringLiteral("--%1 is given %2 times; give it once").arg(displayText(name)).arg(given.count(name)));
    }
    return true;
}

Settings settingsFromOptions(const QCommandLineParser& parser)
{
    const SettingsFromOptions read = readSettingsOptions(parser);
    for (const QString& warning : read.warnings)
        err() << "warning: " << warning << Qt::endl;
    return read.settings;
}

void printFitWarnings(const FittedLight& fit, const QString& context)
{
    for (const SettingsIssue& issue : fitWarnings(fit))
        err() << "warning: " << (context.isEmpty() ? QString() : context + QStringLiteral(": ")) << issue.key << ": " << issue.message << Qt::endl;
}

ProgressBar::ProgressBar() : m_enabled(isatty(STDERR_FILENO) == 1) { m_timer.start(); }

void ProgressBar::show(double fraction, const QString& what)
{
    if (!m_enabled)
        return;
    const int width = 30;
    const int filled = int(fraction * width + 0.5);
    const double elapsed = double(m_timer.elapsed()) / 1000.0;
    const QString left = fraction > 0.02 ? QStringLiteral("%1 s left").arg(int(elapsed / fraction - elapsed + 0.5)) : QStringLiteral("…");
    err() << "\r[" << QString(filled, QLatin1Char('#')) << QString(width - filled, QLatin1Char('.')) << "] "
          << QString::number(int(fraction * 100)).rightJustified(3) << "%  " << left.leftJustified(12) << what.left(40).leftJustified(40)
          << Qt::flush;
}

void ProgressBar::done()
{
    if (m_enabled)
        err() << '\r' << QString(100, QLatin1Char(' ')) << '\r' << Qt::flush;
}

QString formatTexelLine(const FrameStats& stats)
{
    return QStringLiteral("shadow texel: %1 world units as set, %2 as rendered%3%4")
        .arg(stats.texelWorldSizeBeforeFit, 0, 'g', 4)
        .arg(stats.texelWorldSize, 0, 'g', 4)
        .arg(stats.lightFitted ? QStringLiteral(" (fitted to the scene)") : QString(),
             stats.reversedDepth ? QStringLiteral(", reversed depth") : QString());
}

int guarded(const QString& command, const std::function<int()>& body)
{
    try {
        return body();
    } catch (const SceneFileError& e) {
        // A file only too large for an import limit opens with a higher one: this command's option.
        err() << "shadowlab " << command << ": " << e.what();
        if (e.limit() == SceneFileError::Limit::Time)
            err() << " (--import-time-limit SECONDS, now " << importLimits().timeSeconds << ")";
        else if (e.limit() == SceneFileError::Limit::Memory)
            err() << " (--import-memory-limit MIB, now " << importLimits().memoryMiB << ")";
        err() << Qt::endl;
        return kExitBadInput;
    } catch (const SettingsError& e) {
        err() << "shadowlab " << command << ": " << e.what() << (e.isUnknownKey() ? "; run `shadowlab settings` for the list of keys" : "") << Qt::endl;
        return kExitBadInput;
    } catch (const UsageError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitBadInput;
    } catch (const OutputError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return e.kind() == OutputError::Kind::BadLocation ? kExitBadInput : kExitFailure;
    } catch (const RenderError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitFailure;
    } catch (const IoError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitFailure;
    } catch (const TraceError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitFailure;
    }
}

} // namespace shadowlab::cli
