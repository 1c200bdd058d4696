#include "FrameTimeHistory.h"

#include <QCoreApplication>

#include <algorithm>
#include <vector>

namespace shadowlab {

void FrameTimeHistory::add(const FrameStats& stats)
{
    m_frames.push_back({stats.shadowPassRendered, stats.shadowPassWallMs, stats.litPassWallMs, stats.frameWallMs});
    while (int(m_frames.size()) > m_capacity)
        m_frames.pop_front();
}

void FrameTimeHistory::setCapacity(int capacity)
{
    m_capacity = std::max(1, capacity);
    while (int(m_frames.size()) > m_capacity)
        m_frames.pop_front();
}

FrameTimeHistory::Summary FrameTimeHistory::summary() const
{
    std::vector<double> shadow, lit, frame;
    for (const Sample& s : m_frames) {
        if (s.shadowRendered)
            shadow.push_back(s.shadow);
        lit.push_back(s.lit);
        frame.push_back(s.frame);
    }
    return {summarize(shadow), summarize(lit), summarize(frame)};
}

QString FrameTimeHistory::text(const Summary& s, bool cpuTime, bool shadowsOn)
{
    if (s.frame.count == 0)
        return QString();
    const QString shadow = !shadowsOn          ? QStringLiteral("off")
                           : s.shadow.count > 0 ? QStringLiteral("%1").arg(s.shadow.median, 0, 'f', 1)
                                                : QStringLiteral("cached");
    return QCoreApplication::translate("FrameTimeHistory", "shadow %1 · lit %2 · frame %3 ms%4 · median of %5")
        .arg(shadow)
        .arg(s.lit.median, 0, 'f', 1)
        .arg(s.frame.median, 0, 'f', 1)
        .arg(cpuTime ? QCoreApplication::translate("FrameTimeHistory", " CPU") : QString())
        .arg(s.frame.count);
}

bool isSoftwareRenderer(const QString& rendererString)
{
    const QString r = rendererString.toLower();
    return r.contains(QLatin1String("llvmpipe")) || r.contains(QLatin1String("softpipe")) || r.contains(QLatin1String("swrast"))
        || r.contains(QLatin1String("software"));
}

} // namespace shadowlab
