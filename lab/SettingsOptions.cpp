#include "SettingsOptions.h"

#include "ArtifactPresets.h"
#include "ImportLimits.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QFileInfo>
#include <QJsonObject>

namespace shadowlab {

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
    parser.addOption({QStringLiteral("time"),
                      QStringLiteral("Seconds into the scene's animation (scene.time): where its moving objects are."), QStringLiteral("s")});
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
            throw SettingsError(QStringLiteral("--") + option, QStringLiteral("'%1' is not %2, e.g. --%3 %4")
                                            .arg(text, whole ? QStringLiteral("a whole number of MiB") : QStringLiteral("a number of seconds"), option,
                                                 QLatin1String(example)));
        return value;
    };
    ImportLimits limits = importLimits();
    limits.timeSeconds = number(QStringLiteral("import-time-limit"), limits.timeSeconds, false, "60");
    limits.memoryMiB = int(number(QStringLiteral("import-memory-limit"), limits.memoryMiB, true, "8192"));
    setImportLimits(limits);
}

SettingsFromOptions readSettingsOptions(const QCommandLineParser& parser)
{
    SettingsFromOptions result;
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
            result.warnings << QFileInfo(probe.scene).fileName() + QStringLiteral(": ") + warning;
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
    if (parser.isSet(QStringLiteral("time"))) {
        try {
            applySetting(settings, QStringLiteral("scene.time"), parser.value(QStringLiteral("time")));
        } catch (const SettingsError& e) {
            throw SettingsError(QStringLiteral("--time"), QString::fromUtf8(e.what()));
        }
        if (!sceneMoves(settings.scene))
            result.warnings << QStringLiteral("--time: nothing in the scene %1 moves, so its frames are the same at any time").arg(displayText(settings.scene));
    }

    for (const SettingsIssue& issue : validate(settings)) {
        if (issue.severity == SettingsIssue::Severity::Error)
            throw SettingsError(issue.key, issue.message);
        result.warnings << issue.key + QStringLiteral(": ") + escapeControlCharacters(issue.message);
    }
    result.settings = settings;
    return result;
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

} // namespace shadowlab
