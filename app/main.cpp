#include "Application.h"
#include "HeadlessPlatform.h"
#include "CliSupport.h"
#include "cli/Commands.h"

#include <QApplication>
#include <QGuiApplication>

#include <cstdio>
#include <cstring>

namespace {

// The platform Qt will be asked for: "-platform name" (or --platform, or =name) wins over
// QT_QPA_PLATFORM. Empty when neither names one.
QString requestedPlatform(int argc, char* argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QString argument = QString::fromLocal8Bit(argv[i]);
        for (const QString& flag : {QStringLiteral("-platform"), QStringLiteral("--platform")}) {
            if (argument == flag)
                return i + 1 < argc ? QString::fromLocal8Bit(argv[i + 1]) : QStringLiteral(" ");
            if (argument.startsWith(flag + QLatin1Char('=')))
                return argument.mid(flag.size() + 1);
        }
    }
    return qEnvironmentVariable("QT_QPA_PLATFORM");
}

// Qt aborts when no platform it was asked for exists; say so while we still can, naming
// what is available. ("xcb:option" carries options; "a;b" lists fallbacks.)
QString unknownPlatformProblem(const QString& requested)
{
    if (requested.isEmpty())
        return QString();
    const QStringList available = shadowlab::availablePlatformNames();
    const bool haveDisplay = !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    QStringList needDisplay;
    for (const QString& candidate : requested.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QString name = candidate.section(QLatin1Char(':'), 0, 0).trimmed().toLower();
        if (!available.contains(name, Qt::CaseInsensitive))
            continue;
        // Qt aborts when a window-system platform finds no display to connect to.
        if (!haveDisplay && (name == u"xcb" || name.startsWith(u"wayland"))) {
            needDisplay << name;
            continue;
        }
        return QString();
    }
    if (!needDisplay.isEmpty())
        return QStringLiteral("shadowlab: the Qt platform '%1' needs a display and there is none (DISPLAY and WAYLAND_DISPLAY are unset); "
                              "leave QT_QPA_PLATFORM and -platform out to render headless")
            .arg(needDisplay.join(QStringLiteral("', '")));
    return QStringLiteral("shadowlab: there is no Qt platform '%1'; available: %2")
        .arg(shadowlab::displayText(requested), available.join(QStringLiteral(", ")));
}

} // namespace

int main(int argc, char* argv[])
{
    if (argc == 2 && (std::strcmp(argv[1], "--version") == 0 || std::strcmp(argv[1], "-v") == 0)) {
        std::fputs(qPrintable(shadowlab::versionText()), stdout);
        return shadowlab::cli::kExitOk;
    }
    shadowlab::configureApplication();
    if (const QString problem = unknownPlatformProblem(requestedPlatform(argc, argv)); !problem.isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(problem));
        return shadowlab::cli::kExitBadInput;
    }

    QStringList arguments;
    for (int i = 1; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);

    if (!arguments.isEmpty() && shadowlab::cli::isCommand(arguments.first())) {
        // Only commands that build widgets pay for QApplication (styles, fonts, input methods).
        if (shadowlab::cli::needsWidgets(arguments.first())) {
            QApplication app(argc, argv);
            return shadowlab::cli::runCommand(QApplication::arguments().mid(1));
        }
        QGuiApplication app(argc, argv);
        return shadowlab::cli::runCommand(QGuiApplication::arguments().mid(1));
    }
    // `shadowlab help` and `shadowlab help <command>`, as git and cmake users expect.
    if (arguments.value(0) == u"help") {
        if (arguments.size() > 1) {
            if (!shadowlab::cli::isCommand(arguments[1])) {
                QGuiApplication app(argc, argv);
                return shadowlab::cli::unknownCommand(arguments[1]);
            }
            const QStringList help{arguments[1], QStringLiteral("--help")};
            if (shadowlab::cli::needsWidgets(arguments[1])) {
                QApplication app(argc, argv);
                return shadowlab::cli::runCommand(help);
            }
            QGuiApplication app(argc, argv);
            return shadowlab::cli::runCommand(help);
        }
        shadowlab::cli::printUsage(shadowlab::cli::out());
        return shadowlab::cli::kExitOk;
    }
    if (shadowlab::cli::isMistypedCommand(arguments)) {   // `rendr --help` too: not the usage and exit 0
        QGuiApplication app(argc, argv);
        return shadowlab::cli::unknownCommand(arguments.first());
    }
    if (arguments.contains(QStringLiteral("--help")) || arguments.contains(QStringLiteral("-h"))) {
        shadowlab::cli::printUsage(shadowlab::cli::out());
        return shadowlab::cli::kExitOk;
    }
    QApplication app(argc, argv);
    return shadowlab::cli::runExplorer(QApplication::arguments().mid(1)); // without Qt's own options
}
