#include "ArtifactPresets.h"

#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>

#include <algorithm>

namespace shadowlab {

namespace {

const QString kFolder = QStringLiteral(":/presets");
const QString kMetaKey = QStringLiteral("preset");

// A broken preset is a build mistake, not user input: say which file and what is wrong.
[[noreturn]] void brokenPreset(const QString& file, const QString& problem)
{
    throw SettingsError(QStringLiteral("preset"), QStringLiteral("resource %1: %2").arg(file, problem));
}

ArtifactPreset readPreset(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        brokenPreset(path, QStringLiteral("cannot be read"));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        brokenPreset(path, QStringLiteral("is not a JSON object (%1)").arg(error.errorString()));
    QJsonObject object = doc.object();
    const QJsonObject meta = object.take(kMetaKey).toObject();
    ArtifactPreset preset;
    preset.name = QFileInfo(path).completeBaseName();
    preset.title = meta.value(QStringLiteral("title")).toString();
    preset.lookFor = meta.value(QStringLiteral("look_for")).toString();
    preset.fix = meta.value(QStringLiteral("fix")).toString();
    preset.fixSettings = meta.value(QStringLiteral("fix_settings")).toObject();
    preset.order = meta.value(QStringLiteral("order")).toInt();
    preset.settings = object;
    if (preset.title.isEmpty() || preset.lookFor.isEmpty() || preset.fix.isEmpty() || preset.fixSettings.isEmpty())
        brokenPreset(path, QStringLiteral("needs preset.title, preset.look_for, preset.fix and preset.fix_settings"));
    return preset;
}

} // namespace

const std::vector<ArtifactPreset>& artifactPresets()
{
    static const std::vector<ArtifactPreset> presets = [] {
        std::vector<ArtifactPreset> list;
        const QDir folder(kFolder);
        for (const QString& entry : folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
            list.push_back(readPreset(folder.filePath(entry)));
        std::stable_sort(list.begin(), list.end(), [](const ArtifactPreset& a, const ArtifactPreset& b) { return a.order < b.order; });
        return list;
    }();
    return presets;
}

QStringList artifactPresetNames()
{
    QStringList names;
    for (const ArtifactPreset& p : artifactPresets())
        names << p.name;
    return names;
}

const ArtifactPreset& artifactPreset(const QString& name)
{
    const QString wanted = name.trimmed().toLower();
    for (const ArtifactPreset& p : artifactPresets()) {
        if (p.name == wanted)
            return p;
    }
    throw SettingsError(QStringLiteral("preset"), QStringLiteral("'%1' is not an artifact preset; choose one of %2")
                                                      .arg(displayText(name), artifactPresetNames().join(QStringLiteral(", "))));
}

Settings applyArtifactPreset(const ArtifactPreset& preset, const Settings& base)
{
    QJsonObject keys = preset.settings;
    const QString scene = keys.take(QStringLiteral("scene")).toString();
    const Settings start = scene.isEmpty() ? base : presetSettings(scene);
    Settings result = settingsFromJson(keys, start);
    ensureValid(result);
    return result;
}

Settings artifactPresetSettings(const ArtifactPreset& preset)
{
    return applyArtifactPreset(preset, Settings{});
}

Settings artifactPresetFixed(const ArtifactPreset& preset)
{
    Settings fixed = settingsFromJson(preset.fixSettings, artifactPresetSettings(preset));
    ensureValid(fixed);
    return fixed;
}

} // namespace shadowlab
