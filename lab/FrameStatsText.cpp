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

} // namespace shadowlab
