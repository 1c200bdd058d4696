#include "CliSupport.h"

#include "ArtifactPresets.h"
#include "ImportLimits.h"
#include "IoError.h"
#include "Limits.h"
#include "OutputFile.h"
#include "RenderError.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "TraceError.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
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

bool parseArguments(QCommandLineParser& parser, const QString& command, const QStringList& arguments)
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
        out() << "shadowlab " << QCoreApplication::applicationVersion() << Qt::endl;
        return false;
    }
    if (!parser.positionalArguments().isEmpty())
        throw UsageError(QStringLiteral("unexpected argument '%1'; run `%2 --help`").arg(displayText(parser.positionalArguments().first()), invocation));
    // QCommandLineParser keeps the last of a repeated option; a user who wrote two meant something.
    const QStringList given = parser.optionNames();
    for (const QString& name : given) {
        if (name != u"set" && name != u"set-b" && given.count(name) > 1)
            throw UsageError(QStringLiteral("--%1 is given %2 times; give it once").arg(displayText(name)).arg(given.count(name)));
    }
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
    parser.addOption({QStringLiteral("preset"),
                      QStringLiteral("Start from an artifact preset (%1): its scene and the settings that show the artifact.")
                          .arg(artifactPresetNames().join(QStringLiteral(", "))),
                      QStringLiteral("name")});
    addImportOptions(parser);
}

void addImportOptions(QCommandLineParser& parser)
{
    const ImportLimits defaults;
    parser.addOption({QStringLiteral("import-time-limit"),
                      QStringLiteral("Seconds the importer may take to read a model file before it is stopped (default %1).").arg(defaults.timeSeconds),
                      QStringLiteral("s")});
    parser.addOption({QStringLiteral("import-memory-limit"),
                      QStringLiteral("Memory in MiB the importer may use for a model file (default %1).").arg(defaults.memoryMiB),
                      QStringLiteral("MiB")});
}

void applyImportOptions(const QCommandLineParser& parser)
{
    // The option's value as a number, or `fallback` when it is not given.
    const auto number = [&parser](const QString& option, double fallback, bool whole, const char* example) {
        if (!parser.isSet(option))
            return fallback;
        bool ok = false;
        const QString text = parser.value(option);
        const double value = whole ? double(text.toInt(&ok)) : text.toDouble(&ok);
        if (!ok)
            throw SettingsError(option, QStringLiteral("'%1' is not %2, e.g. --%3 %4")
                                            .arg(text, whole ? QStringLiteral("a whole number of MiB") : QStringLiteral("a number of seconds"), option,
                                                 QLatin1String(example)));
        return value;
    };
    ImportLimits limits = importLimits();
    limits.timeSeconds = number(QStringLiteral("import-time-limit"), limits.timeSeconds, false, "60");
    limits.memoryMiB = int(number(QStringLiteral("import-memory-limit"), limits.memoryMiB, true, "8192"));
    setImportLimits(limits);
}

Settings settingsFromOptions(const QCommandLineParser& parser)
{
    applyImportOptions(parser);
    const QStringList assignments = parser.values(QStringLiteral("set"));
    const QString file = parser.value(QStringLiteral("settings"));

    // Read once: the file may be a pipe.
    const QJsonObject fileObject = file.isEmpty() ? QJsonObject() : readSettingsObject(file);
    const ArtifactPreset* preset = parser.isSet(QStringLiteral("preset")) ? &artifactPreset(parser.value(QStringLiteral("preset"))) : nullptr;
    QString scene = QStringLiteral("seed");
    if (preset && preset->settings.contains(QStringLiteral("scene")))
        scene = preset->settings.value(QStringLiteral("scene")).toString();
    if (const QString fileScene = fileObject.value(QStringLiteral("scene")).toString(); !fileScene.isEmpty())
        scene = fileScene;
    if (parser.isSet(QStringLiteral("scene")))
        scene = parser.value(QStringLiteral("scene"));
    for (const QString& a : assignments) {
        if (a.section(QLatin1Char('='), 0, 0).trimmed() == u"scene")
            scene = a.section(QLatin1Char('='), 1);
    }
    Settings probe;
    applySetting(probe, QStringLiteral("scene"), scene); // validates the name with a helpful message

    Settings settings = presetSettings(probe.scene);
    if (!isPresetName(probe.scene)) {
        for (const QString& warning : loadSceneFile(probe.scene)->warnings)
            err() << "warning: " << QFileInfo(probe.scene).fileName() << ": " << warning << Qt::endl;
    }
    if (preset) {
        QJsonObject keys = preset->settings;
        keys.remove(QStringLiteral("scene"));   // an explicit --scene wins over the preset's
        settings = settingsFromJson(keys, settings);
    }
    if (!file.isEmpty())
        settings = settingsFromFileObject(file, fileObject, settings);
    for (const QString& a : assignments)
        applyAssignment(settings, a);
    settings.scene = probe.scene;

    for (const SettingsIssue& issue : validate(settings)) {
        if (issue.severity == SettingsIssue::Severity::Error)
            throw SettingsError(issue.key, issue.message);
        err() << "warning: " << issue.key << ": " << escapeControlCharacters(issue.message) << Qt::endl;
    }
    return settings;
}

void printFitWarnings(const FittedLight& fit, const QString& context)
{
    for (const SettingsIssue& issue : fit.warnings)
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

QSize parseSize(const QString& text, const QString& option, const SizeLimits& limits)
{
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = parts.size() == 2 ? parts[0].toInt(&okW) : 0;
    const int h = parts.size() == 2 ? parts[1].toInt(&okH) : 0;
    if (!okW || !okH)
        throw UsageError(QStringLiteral("--%1: '%2' is not a size; write WIDTHxHEIGHT, e.g. 1280x720").arg(option, displayText(text)));
    const QSize size(w, h);
    auto sizeText = [](QSize s) { return QStringLiteral("%1x%2").arg(s.width()).arg(s.height()); };
    if (w < limits.minimum.width() || h < limits.minimum.height())
        throw UsageError(QStringLiteral("--%1: %2 is too small; the minimum is %3").arg(option, sizeText(size), sizeText(limits.minimum)));
    if (w > limits.maximum.width() || h > limits.maximum.height())
        throw UsageError(QStringLiteral("--%1: %2 is too large; the maximum is %3 (%4)")
                             .arg(option, sizeText(size), sizeText(limits.maximum), limits.reason));
    return size;
}

int parseCount(const QString& text, const QString& option, int minimum, int maximum)
{
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < minimum || value > maximum)
        throw UsageError(QStringLiteral("--%1: '%2' is not allowed; give a whole number in [%3, %4]").arg(option, displayText(text)).arg(minimum).arg(maximum));
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
