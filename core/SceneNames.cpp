#include "SceneNames.h"

namespace shadowlab {

const QStringList& sceneNames()
{
    static const QStringList names{QStringLiteral("seed"), QStringLiteral("torus"), QStringLiteral("cubes"), QStringLiteral("occluder"),
                                   QStringLiteral("bleeding"), QStringLiteral("foliage"), QStringLiteral("city")};
    return names;
}

int cityBuildingCount(const QString& name)
{
    if (name == u"city")
        return kCityBuildings;
    if (!name.startsWith(QStringLiteral("city:")))
        return 0;
    bool ok = false;
    const int count = name.mid(5).toInt(&ok);
    return ok && count >= 1 && count <= kMaxCityBuildings ? count : -1;
}

bool isPresetName(const QString& name)
{
    return sceneNames().contains(name) || cityBuildingCount(name) > 0;
}

} // namespace shadowlab
