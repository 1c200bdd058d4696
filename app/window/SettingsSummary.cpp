#include "SettingsSummary.h"

#include "MomentMath.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"
#include "VirtualPages.h"

#include <QFileInfo>

namespace shadowlab {

QString squareSize(int side)
{
    // Appended, not in the format string: QString::arg() would read "%1²" as a two-digit placeholder.
    return QString::number(side) + QChar(0x00B2);
}

QString mapLayoutSummary(const Settings& settings)
{
    const QString side = squareSize(settings.map.size);
    if (settings.shadow.virtualMap) {
        const int pool = settings.shadow.virtualPool;
        return QStringLiteral("virtual map of %1 pages of %2").arg(pool * pool).arg(squareSize(kVirtualPageTexels));
    }
    if (settings.light.type == LightType::Point)
        return QStringLiteral("six %1 cube faces").arg(side);
    if (usesShadowViews(settings))
        return QStringLiteral("%1 cascades of %2").arg(settings.shadow.cascades).arg(side);
    return QStringLiteral("%1 %2").arg(side, toString(settings.light.projection));
}

QString settingsSummary(const Settings& settings)
{
    if (!settings.shadow.enabled)
        return QStringLiteral("%1 · shadows off").arg(toString(settings.shading.model));
    QString text = QStringLiteral("%1 · slope %2 · min %3 · %4")
                       .arg(filterLabel(settings.filter))
                       .arg(settings.bias.slope, 0, 'g', 3)     // a caption, not the value: the dock has it whole
                       .arg(settings.bias.min, 0, 'g', 3)
                       .arg(mapLayoutSummary(settings));
    // A moments map draws every face with no offset (MomentsPass): neither applies to it.
    const bool depthMap = !isMomentTechnique(settings.filter.mode);
    if (depthMap && settings.bias.cullFront)
        text += QStringLiteral(" · front faces culled");
    if (depthMap && (settings.bias.polygonFactor != 0.0 || settings.bias.polygonUnits != 0.0))
        text += QStringLiteral(" · offset %1, %2").arg(settings.bias.polygonFactor, 0, 'g', 3).arg(settings.bias.polygonUnits, 0, 'g', 4);
    return text;
}

QString comparedSummary(const Settings& side, const Settings& other)
{
    constexpr int kShown = 3;
    QStringList differences;
    int more = 0;
    for (const SettingKey& key : settingKeys()) {
        const QString mine = settingValue(side, key.key);
        if (key.key == u"scene" || mine == settingValue(other, key.key))
            continue;
        if (differences.size() < kShown)
            differences << QStringLiteral("%1 %2").arg(key.key, mine);
        else
            ++more;
    }
    if (differences.isEmpty())
        return QStringLiteral("the same settings · %1").arg(settingsSummary(side));
    if (more > 0)
        differences << QStringLiteral("%1 more").arg(more);
    return QStringLiteral("%1 — %2").arg(differences.join(QStringLiteral(" · ")), settingsSummary(side));
}

QString screenshotFileName(const Settings& settings, const QDateTime& when)
{
    // The label without spaces or signs a file name would not want: "pcf 5×5" -> "pcf5".
    QString filter = filterLabel(settings.filter).section(QChar(0x00D7), 0, 0).remove(QLatin1Char(' '));
    const QString technique = settings.shadow.enabled ? QStringLiteral("%1-%2").arg(filter).arg(settings.map.size)
                                                      : QStringLiteral("noshadow");
    return QStringLiteral("shadowlab-%1-%2-%3.png").arg(when.toString(QStringLiteral("yyyy-MM-dd-HHmm")),
                                                            QFileInfo(settings.scene).completeBaseName(), technique);
}

QString shadowMapSummary(const Settings& shown)
{
    // What the map holds: depth in its format, or a moment technique's moments.
    const bool moments = isMomentTechnique(shown.filter.mode);
    const QString holds = moments ? QStringLiteral("moments RGBA%1F").arg(toString(shown.moments.format)) : toString(shown.map.format);
    if (!shown.shadow.enabled)
        return QStringLiteral("shadows are off");
    if (shown.shadow.virtualMap) {
        const int pool = shown.shadow.virtualPool;
        return QStringLiteral("virtual map, a pool of %1 pages of %2 (%3 %4)")
            .arg(pool * pool)
            .arg(squareSize(kVirtualPageTexels))
            .arg(squareSize(pool * kVirtualSlotTexels), holds);
    }
    if (shown.light.type == LightType::Point)
        return QStringLiteral("point light, six cube faces of %1, %2").arg(squareSize(shown.map.size), holds);
    if (usesShadowViews(shown))
        return QStringLiteral("%1 cascades of %2, %3").arg(shown.shadow.cascades).arg(squareSize(shown.map.size), holds);
    return QStringLiteral("%1 light, %2").arg(toString(shown.light.projection), holds);
}

} // namespace shadowlab
