#include "SceneNames.h"

namespace shadowlab {

const QStringList& sceneNames()
{
    static const QStringList names{QStringLiteral("seed"), QStringLiteral("torus"), QStringLiteral("cubes"), QStringLiteral("occluder"),
                                   QStringLiteral("bleeding")};
    return names;
}

} // namespace shadowlab
