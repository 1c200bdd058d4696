#include "FrameStatsText.h"

#include <algorithm>
#include <map>

#include <QCoreApplication>

namespace shadowlab {

QString warpStatusText(const FrameStats& stats)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("FrameStats", text); };
    if (stats.warpViews == 0)
        return {};
    if (stats.warpedViews > 0) {
        const QString views = stats.warpViews > 1 ? tr("on %1 of %2 views, ").arg(stats.warpedViews).arg(stats.warpViews) : QString();
        return tr("lispsm warp %1texels nearest the camera %2× finer than unwarped").arg(views).arg(stats.warpGain, 0, 'f', 2);
    }
    if (stats.warpDeclined == FrameStats::WarpDeclined::NoGain)
        return tr("lispsm warp not drawn: it would make the texels nearest the camera only %1× as fine as unwarped").arg(stats.warpGain, 0, 'f', 2);
    return tr("lispsm warp not drawn: the camera looks along the light, where no warp helps");
}

QString redrawStatusText(const FrameStats& stats)
{
    using Redraw = FrameStats::Redraw;
    static const std::map<Redraw, QString> why{{Redraw::Scene, QStringLiteral("new scene")},     {Redraw::Casters, QStringLiteral("casters moved")},
                                               {Redraw::Light, QStringLiteral("light moved")},   {Redraw::Camera, QStringLiteral("camera moved")},
                                               {Redraw::Settings, QStringLiteral("settings changed")}};
    const auto reason = why.find(stats.redraw);
    if (reason == why.end())
        return {};
    if (stats.viewRendered.empty())
        return QStringLiteral("redrawn: %1").arg(reason->second);
    const auto drawn = std::count(stats.viewRendered.begin(), stats.viewRendered.end(), true);
    return QStringLiteral("%1 of %2 views redrawn: %3").arg(drawn).arg(stats.viewRendered.size()).arg(reason->second);
}

QString cacheStatusText(const FrameStats& stats)
{
    std::map<ViewCause, int> counts;
    for (ViewCause cause : stats.viewCauses)
        ++counts[cause];
    for (const auto& [slot, cause] : stats.pageCauses)
        ++counts[cause];
    if (counts.empty())
        return {};
    QStringList parts;
    for (const auto& [cause, count] : counts)
        parts << QStringLiteral("%1 %2").arg(count).arg(toString(cause));
    QString text = QStringLiteral("cache: %1").arg(parts.join(QStringLiteral(", ")));
    if (stats.cacheBytes > 0)
        text += QStringLiteral(" · copies %1").arg(bytesText(stats.cacheBytes));
    return text;
}

QString virtualMapStatusText(const FrameStats& stats)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("FrameStats", text); };
    if (!stats.virtualMap)
        return {};
    const VirtualMapStats& v = stats.virtualPages;
    QString text = tr("virtual map: %1 pages requested, %2 resident of %3, %4 drawn this frame")
                       .arg(v.requested).arg(v.resident).arg(v.poolPages).arg(v.drawn);
    if (v.coarsened > 0)
        text += tr("; the pool is too small for this view: %1 pages coarsened by up to %2 levels (raise shadow.virtual_pool)")
                    .arg(v.coarsened).arg(v.levelsCoarsened);
    if (v.overflow > 0)
        text += tr("; %1 pages of the coarsest level did not fit and read lit (raise shadow.virtual_pool)").arg(v.overflow);
    return text;
}

QString countText(std::int64_t count)
{
    if (count < 0)
        return QStringLiteral("n/a");
    const double c = double(count);
    if (count < 1000)
        return QString::number(count);
    if (c < 1e6)
        return QStringLiteral("%1 k").arg(c / 1e3, 0, 'f', c < 1e4 ? 2 : 1);
    if (c < 1e9)
        return QStringLiteral("%1 M").arg(c / 1e6, 0, 'f', c < 1e7 ? 2 : 1);
    return QStringLiteral("%1 G").arg(c / 1e9, 0, 'f', 2);
}

QString bytesText(std::int64_t bytes)
{
    const double mib = double(bytes) / double(1 << 20);
    return mib >= 10.0 ? QStringLiteral("%1 MiB").arg(mib, 0, 'f', 0) : QStringLiteral("%1 MiB").arg(mib, 0, 'f', 1);
}

QStringList countsLines(const FrameCounts& c)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("FrameStats", text); };
    QStringList lines;
    lines << tr("shadow pass: %1 draws, %2 triangles, %3 samples, %4 texels cleared, map %5")
                 .arg(c.shadow.draws)
                 .arg(countText(c.shadow.primitives), countText(c.shadow.samples), countText(c.clearedTexels), bytesText(c.mapBytes));
    if (c.cacheBytes > 0)
        lines << tr("  shadow.cache: %1 texels copied, copies %2").arg(countText(c.copiedTexels), bytesText(c.cacheBytes));
    if (c.blurTexels > 0)
        lines << tr("  of which blur: %1 texels written, %2 read and written").arg(countText(c.blurTexels), bytesText(c.blurBytes));
    QString lit = tr("lit pass: %1 draws, %2 triangles, %3 samples").arg(c.lit.draws).arg(countText(c.lit.primitives), countText(c.lit.samples));
    if (c.tapsPerLookup > 0)
        lit += c.tapsPerLookup == 1 ? tr(", %1 lookups of 1 tap").arg(countText(c.lookupFragments))
                                    : tr(", %1 lookups of %2 taps = %3 taps").arg(countText(c.lookupFragments)).arg(c.tapsPerLookup).arg(countText(c.taps()));
    lines << lit;
    return lines;
}

QJsonObject countsJson(const FrameCounts& c)
{
    const auto counted = [](std::int64_t n) { return n < 0 ? QJsonValue() : QJsonValue(double(n)); };
    const auto pass = [&](const PassCounts& p) {
        return QJsonObject{{QStringLiteral("draws"), p.draws}, {QStringLiteral("primitives"), counted(p.primitives)}, {QStringLiteral("samples"), counted(p.samples)}};
    };
    return {{QStringLiteral("shadow_pass"), pass(c.shadow)},
            {QStringLiteral("lit_pass"), pass(c.lit)},
            {QStringLiteral("cleared_texels"), double(c.clearedTexels)},
            {QStringLiteral("blur_texels"), double(c.blurTexels)},
            {QStringLiteral("blur_bytes"), double(c.blurBytes)},
            {QStringLiteral("map_bytes"), double(c.mapBytes)},
            {QStringLiteral("copied_texels"), double(c.copiedTexels)},
            {QStringLiteral("cache_bytes"), double(c.cacheBytes)},
            {QStringLiteral("taps_per_lookup"), c.tapsPerLookup},
            {QStringLiteral("lookup_fragments"), counted(c.lookupFragments)},
            {QStringLiteral("taps"), counted(c.taps())}};
}

} // namespace shadowlab
