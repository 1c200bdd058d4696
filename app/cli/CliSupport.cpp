#include "CliSupport.h"

#include "IoError.h"
#include "Limits.h"
#include "RenderError.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "TraceError.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

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

bool parseArguments(QCommandLineParser& parser, const QString& command, const QStringList& arguments)
{
    if (!parser.parse(QStringList{QStringLiteral("shadowlab ") + command} + arguments))
        throw UsageError(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out() << parser.helpText();
        return false;
    }
    if (!parser.positionalArguments().isEmpty())
        throw UsageError(QStringLiteral("unexpected argument '%1'; run `shadowlab %2 --help`").arg(parser.positionalArguments().first(), command));
    return true;
}

void addSettingsOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("scene"),
                      QStringLiteral("Scene preset (%1), or a model file (glTF, OBJ, PLY, STL, COLLADA, FBX) or scene file (.json).")
                          .arg(sceneNames().join(QStringLiteral(", "))),
                      QStringLiteral("name|file")});
    parser.addOption({QStringLiteral("set"), QStringLiteral("Set one setting, e.g. --set bias.slope=0.01 (repeatable; see `shadowlab settings`)."),
                      QStringLiteral("key=value")});
    parser.addOption({QStringLiteral("settings"), QStringLiteral("Read settings from a JSON file of key: value pairs."),
                      QStringLiteral("file.json")});
}

namespace {

QString sceneOfFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QString(); // loadSettingsFile() reports the error with the file's name
    const QJsonObject object = QJsonDocument::fromJson(file.readAll()).object();
    return object.value(QStringLiteral("scene")).toString();
}

} // namespace

Settings settingsFromOptions(const QCommandLineParser& parser)
{
    const QStringList assignments = parser.values(QStringLiteral("set"));
    const QString file = parser.value(QStringLiteral("settings"));

    QString scene = QStringLiteral("seed");
    if (!file.isEmpty() && !sceneOfFile(file).isEmpty())
        scene = sceneOfFile(file);
    if (parser.isSet(QStringLiteral("scene")))
        scene = parser.value(QStringLiteral("scene"));
    for (const QString& a : assignments) {
        if (a.section(QLatin1Char('='), 0, 0).trimmed() == u"scene")
            scene = a.section(QLatin1Char('='), 1);
    }
    Settings probe;
    applySetting(probe, QStringLiteral("scene"), scene); // validates the name with a helpful message

    Settings settings = presetSettings(probe.scene);
    if (!sceneNames().contains(probe.scene)) {
        for (const QString& warning : loadSceneFile(probe.scene)->warnings)
            err() << "warning: " << QFileInfo(probe.scene).fileName() << ": " << warning << Qt::endl;
    }
    if (!file.isEmpty())
        settings = loadSettingsFile(file, settings);
    for (const QString& a : assignments)
        applyAssignment(settings, a);
    settings.scene = probe.scene;

    for (const SettingsIssue& issue : validate(settings)) {
        if (issue.severity == SettingsIssue::Severity::Error)
            throw SettingsError(issue.key, issue.message);
        err() << "warning: " << issue.key << ": " << issue.message << Qt::endl;
    }
    return settings;
}

void printFitWarnings(const FittedLight& fit, const QString& context)
{
    for (const SettingsIssue& issue : fit.warnings)
        err() << "warning: " << (context.isEmpty() ? QString() : context + QStringLiteral(": ")) << issue.key << ": " << issue.message << Qt::endl;
}

QString formatTexelLine(const FrameStats& stats)
{
    return QStringLiteral("shadow texel: %1 world units as set, %2 as rendered%3%4")
        .arg(stats.texelWorldSizeBeforeFit, 0, 'g', 4)
        .arg(stats.texelWorldSize, 0, 'g', 4)
        .arg(stats.lightFitted ? QStringLiteral(" (fitted to the scene)") : QString(),
             stats.reversedDepth ? QStringLiteral(", reversed depth") : QString());
}

QSize parseSize(const QString& text, const QString& option)
{
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = parts.size() == 2 ? parts[0].toInt(&okW) : 0;
    const int h = parts.size() == 2 ? parts[1].toInt(&okH) : 0;
    if (!okW || !okH)
        throw UsageError(QStringLiteral("--%1: '%2' is not a size; write WIDTHxHEIGHT, e.g. 1280x720").arg(option, text));
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        throw UsageError(QStringLiteral("--%1: %2 is out of range; width and height must be in [1, %3]").arg(option, text).arg(kMaxImageSide));
    return {w, h};
}

int parseCount(const QString& text, const QString& option, int minimum, int maximum)
{
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < minimum || value > maximum)
        throw UsageError(QStringLiteral("--%1: '%2' is not allowed; give a whole number in [%3, %4]").arg(option, text).arg(minimum).arg(maximum));
    return value;
}

int guarded(const QString& command, const std::function<int()>& body)
{
    try {
        return body();
    } catch (const SettingsError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitBadInput;
    } catch (const UsageError& e) {
        err() << "shadowlab " << command << ": " << e.what() << Qt::endl;
        return kExitBadInput;
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
