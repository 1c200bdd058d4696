#include "FrameStatsText.h"

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

} // namespace shadowlab
