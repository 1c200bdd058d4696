#include "SettingsSceneKeys.h"

#include "MessageText.h"
#include "SceneNames.h"
#include "SettingsError.h"

#include <QFileInfo>

// The schema's keys that name the scene and its objects (the rest are in SettingsTable.cpp).
namespace shadowlab::settings {

Entry sceneKey(const SettingPresentation& look)
{
    const QStringList names = sceneNames();
    const QString rangeText = names.join(QStringLiteral(" | ")) + QStringLiteral(" | city:N (N buildings, 1..%1) | city+V or city:N+V (V vehicles driving, 0..%2) | a model or scene file")
                                                                        .arg(kMaxCityBuildings).arg(kMaxCityVehicles);
    const KeySpec spec{.key = "scene",
                       .help = "Built-in scene preset, or the path of a model (glTF, OBJ, PLY, STL, COLLADA, FBX) or scene file (.json); "
                               "choosing one also resets light and camera to the scene's",
                       .look = look};
    const auto missing = [names](const QString& v) {
        return QStringLiteral("'%1': no such file, and not a preset (%2)").arg(displayText(v), names.join(QStringLiteral(" | ")));
    };
    return {describe(spec, "choice", rangeText, 0, double(names.size() - 1), names),
            [](const Settings& s) { return s.scene; },
            [names, missing](Settings& s, const QString& v) {
                const QString name = v.trimmed().toLower();
                if (isPresetName(name)) {
                    s.scene = name;
                    return;
                }
                if (cityBuildingCount(name) < 0 && !QFileInfo(v.trimmed()).isFile())
                    throw SettingsError(QStringLiteral("scene"), QStringLiteral("'%1': a city's building count must be a whole number in [1, %2] and its "
                                                                                "vehicles one in [0, %3], e.g. city:8000 or city+50")
                                                                     .arg(displayText(v)).arg(kMaxCityBuildings).arg(kMaxCityVehicles));
                const QFileInfo file(v.trimmed());
                if (!file.isFile())
                    throw SettingsError(QStringLiteral("scene"), QStringLiteral("%1%2; check the path").arg(missing(v), didYouMean(v, names)));
                s.scene = file.absoluteFilePath();
            },
            [missing](const Settings& s) -> std::optional<QString> {
                if (!isPresetName(s.scene) && !QFileInfo(s.scene).isFile())
                    return QStringLiteral("%1; check the path").arg(missing(s.scene));
                return std::nullopt;
            }};
}

// A list of the scene's objects (ObjectSwitches): names, or #i, separated by commas. Whether
// they are in the scene is checked where the scene is built (it is not known here).
Entry objectSwitchKey(const char* key, const char* help, const QString& label, QLatin1String group, QStringList ObjectSwitches::*list)
{
    const QString k = QString::fromLatin1(key);
    const KeySpec spec{.key = key, .help = help, .look = {.label = label, .group = group}};
    return {describe(spec, "objects", QStringLiteral("names or #i, comma-separated; empty: none"), 0.0, 0.0),
            [list](const Settings& s) { return (s.objects.*list).join(QLatin1Char(',')); },
            [list, k](Settings& s, const QString& v) {
                QStringList names;
                for (const QString& part : v.split(QLatin1Char(','))) {
                    const QString name = part.trimmed();
                    if (name.isEmpty())
                        continue;
                    if (name.startsWith(u'#')) {
                        bool ok = false;
                        const int i = name.mid(1).toInt(&ok);
                        if (!ok || i < 0)
                            throw SettingsError(k, QStringLiteral("'%1': #i must name an object by its index, a whole number from 0, e.g. #3")
                                                       .arg(displayText(name)));
                    }
                    if (!names.contains(name))
                        names << name;
                }
                s.objects.*list = names;
            },
            noCheck};
}

} // namespace shadowlab::settings
