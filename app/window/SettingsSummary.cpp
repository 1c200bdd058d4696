#include "SettingsSummary.h"

#include "MomentMath.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

#include <QFileInfo>

namespace shadowlab {

QString squareSize(int side)
{
    // Appended, not in the format string: QString::arg() would read "%1²" as a two-digit placeholder.
    return QString::number(side) + QChar(0x00B2);
}

QString settingsSummary(const Settings& settings)
{
    if (!settings.shadow.enabled)
        return QStringLiteral("%1 · shadows off").arg(toString(settings.shading.model));
    QString text = QStringLiteral("%1 · slope %2 · min %3 · %4 %5")
                       .arg(filterLabel(settings.filter))
                       .arg(settings.bias.slope, 0, 'g', 3)     // a caption, not the value: the dock has it whole
                       .arg(settings.bias.min, 0, 'g', 3)
                       .arg(squareSize(settings.map.size), toString(settings.light.projection));
    if (settings.bias.cullFront)
        text += QStringLiteral(" · front faces culled");
    if (settings.bias.polygonFactor != 0.0 || settings.bias.polygonUnits != 0.0)
        text += QStringLiteral(" · offset %1, %2").arg(settings.bias.polygonFactor, 0, 'g', 3).arg(settings.bias.polygonUnits, 0, 'g', 4);
    return text;
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
    const QString light = QStringLiteral("%1 light, %2").arg(toString(shown.light.projection), holds);
    return shown.shadow.enabled ? light : QStringLiteral("shadows are off");
}

} // namespace shadowlab
