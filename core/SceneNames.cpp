#include "SceneNames.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <utility>
#include <vector>

namespace shadowlab {

const QStringList& sceneNames()
{
    // One resource file per preset (resources/scenes/NAME.json, which the scene library carries),
    // listed in the order each file gives itself.
    static const QStringList names = [] {
        std::vector<std::pair<double, QString>> found;
        for (const QFileInfo& info : QDir(QString::fromLatin1(kScenePresetFolder)).entryInfoList({QStringLiteral("*.json")}, QDir::Files)) {
            QFile file(info.filePath());
            const double order = file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("order")).toDouble(1e9)
                                                                : 1e9;
            found.emplace_back(order, info.completeBaseName());
        }
        std::sort(found.begin(), found.end());
        QStringList list;
        for (const auto& [order, name] : found)
            list << name;
        return list;
    }();
    return names;
}

int cityBuildingCount(const QString& name)
{
    const QString buildings = name.section(u'+', 0, 0);
    if (!buildings.startsWith(QStringLiteral("city")))
        return 0;
    if (cityVehicleCount(name) < 0)
        return -1;
    if (buildings == u"city")
        return kCityBuildings;
    if (!buildings.startsWith(QStringLiteral("city:")))
        return 0;
    bool ok = false;
    const int count = buildings.mid(5).toInt(&ok);
    return ok && count >= 1 && count <= kMaxCityBuildings ? count : -1;
}

int cityVehicleCount(const QString& name)
{
    if (!name.startsWith(QStringLiteral("city")))
        return -1;
    if (!name.contains(u'+'))
        return 0;
    bool ok = false;
    const int count = name.section(u'+', 1).toInt(&ok);
    return ok && count >= 0 && count <= kMaxCityVehicles && !name.section(u'+', 1).startsWith(u'+') ? count : -1;
}

bool isPresetName(const QString& name)
{
    return sceneNames().contains(name) || cityBuildingCount(name) > 0;
}

} // namespace shadowlab
