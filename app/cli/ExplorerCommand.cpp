#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessPlatform.h"
#include "MainWindow.h"
#include "PropertiesDock.h"
#include "SceneNames.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "StopSignals.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QRegularExpression>

#include <optional>

namespace shadowlab::cli {

namespace {

// The settings options that take a value: a word after one of them is that value, not a file.
bool takesValue(const QString& argument)
{
    for (const char* option : {"--scene", "--set", "--settings", "--preset", "--import-time-limit", "--import-memory-limit"}) {
        if (argument == QLatin1String(option))
            return true;
    }
    return false;
}

// `word` as a POSIX shell reads it back: as it is where it holds nothing the shell treats
// specially, else in single quotes.
QString shellWord(const QString& word)
{
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z0-9_./:=,+-]+$"));
    if (plain.match(word).hasMatch())
        return word;
    return QStringLiteral("'%1'").arg(QString(word).replace(QLatin1Char('\''), QStringLiteral("'\\''")));
}

// A file named on its own (as a file manager starts a program) is --scene file.
QStringList fileAsSceneOption(const QStringList& arguments)
{
    QStringList rewritten;
    bool named = false;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString& a = arguments[i];
        const bool value = i > 0 && takesValue(arguments[i - 1]);
        if (!a.startsWith(QLatin1Char('-')) && !value && !named) {
            rewritten << QStringLiteral("--scene") << a;
            named = true;
        } else {
            rewritten << a;
        }
    }
    if (named && arguments.contains(QStringLiteral("--scene")))
        throw UsageError(QStringLiteral("a file and --scene both name the scene; give one of them"));
    return rewritten;
}

// What the explorer's options ask for.
struct ExplorerRequest {
    std::optional<Settings> settings;   // side A's, where options gave any
    QString preset;
    QString backgroundScene;            // a model or scene file alone, read in the window
    QStringList given;                  // the options as parsed (a file named alone as --scene file)
};

// The request of non-empty `arguments`; nullopt where help was asked for (and printed).
// Throws SettingsError and UsageError.
std::optional<ExplorerRequest> parseExplorerOptions(const QStringList& arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Open the explorer window. With settings options, side A starts from them instead of the last "
                       "session's settings; a model or scene file alone opens it, as --scene does."));
    parser.addHelpOption();
    addSettingsOptions(parser);
    parser.addPositionalArgument(QStringLiteral("file"), QStringLiteral("A model or scene file to open (the same as --scene file)."),
                                 QStringLiteral("[file]"));
    ExplorerRequest request;
    request.given = fileAsSceneOption(arguments);
    if (!parseArguments(parser, QString(), request.given))
        return std::nullopt;
    applyImportOptions(parser);
    // A file alone (as a file manager starts a program) opens in the window, in the
    // background; with other settings on top, or with no display to open on, it is read
    // first, like every command does, and a refusal is exit code 2.
    const bool onlyAFile = !headlessPlatformNames().contains(QGuiApplication::platformName()) && parser.isSet(QStringLiteral("scene"))
                           && !parser.isSet(QStringLiteral("set")) && !parser.isSet(QStringLiteral("settings")) && !parser.isSet(QStringLiteral("preset"));
    if (onlyAFile) {
        Settings probe;
        applySetting(probe, QStringLiteral("scene"), parser.value(QStringLiteral("scene")));   // a missing file: exit 2 now
        if (!isPresetName(probe.scene))
            request.backgroundScene = probe.scene;
    }
    if (request.backgroundScene.isEmpty())
        request.settings = settingsFromOptions(parser);
    request.preset = parser.value(QStringLiteral("preset"));
    return request;
}

// A window nobody can see would run forever: says what to do instead, with the same settings
// offscreen (the options the window was given, quoted for a shell).
int refuseWithoutDisplay(const QStringList& given)
{
    QStringList same;
    for (const QString& a : given)
        same << shellWord(a);
    err() << "shadowlab: there is no display, so the explorer cannot open.\n"
          << "Render it offscreen instead: shadowlab screenshot " << (same.isEmpty() ? QString() : same.join(QLatin1Char(' ')) + QLatin1Char(' '))
          << "--out window.png" << Qt::endl;
    return kExitBadInput;
}

int openExplorer(const ExplorerRequest& request)
{
    MainWindow window;
    if (request.settings) {
        window.setSettings(MainWindow::Side::A, *request.settings, QApplication::translate("Explorer", "Start from the command line's settings"));
        if (!request.preset.isEmpty())
            window.propertiesDock()->showPreset(request.preset);
    }
    // A logout or `kill` closes the window as the user would; where the process cannot have
    // that (no socket pair to spare), a signal stops it as it would any program.
    std::optional<StopSignals> stop;
    try {
        stop.emplace();
    } catch (const std::runtime_error& e) {
        err() << "shadowlab: " << e.what() << "; a logout or `kill` will stop the explorer without saving the session" << Qt::endl;
    }
    window.show();
    if (!request.backgroundScene.isEmpty())
        window.openSceneInBackground(request.backgroundScene);
    return QApplication::exec();
}

} // namespace

int runExplorer(const QStringList& arguments)
{
    // Before the word is taken for a model file: with options after it, it would be refused for
    // what follows ("a file and --scene both name the scene") instead of for what it is.
    if (isMistypedCommand(arguments))
        return unknownCommand(arguments.first());
    ExplorerRequest request;
    try {
        if (!arguments.isEmpty()) {
            const std::optional<ExplorerRequest> parsed = parseExplorerOptions(arguments);
            if (!parsed)
                return kExitOk;
            request = *parsed;
        }
    } catch (const SettingsError& e) {
        err() << "shadowlab: " << e.what() << (e.isUnknownKey() ? "; run `shadowlab settings` for the list of keys" : "") << Qt::endl;
        return kExitBadInput;
    } catch (const UsageError& e) {
        err() << "shadowlab: " << e.what() << Qt::endl;
        return kExitBadInput;
    }
    if (headlessPlatformNames().contains(QGuiApplication::platformName()))
        return refuseWithoutDisplay(request.given);
    return openExplorer(request);
}

} // namespace shadowlab::cli
