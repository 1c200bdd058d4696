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
    std::vector<double> shadow, lit, frame, withShadow, withoutShadow;
    for (const Sample& s : m_frames) {
        if (s.shadowRendered)
            shadow.push_back(s.shadow);
        lit.push_back(s.lit);
        frame.push_back(s.frame);
        (s.shadowRendered ? withShadow : withoutShadow).push_back(s.frame);
    }
    return {summarize(shadow), summarize(lit), summarize(frame), summarize(withShadow), summarize(withoutShadow)};
}

QString FrameTimeHistory::text(const Summary& s, bool cpuTime, bool shadowsOn)
{
    if (s.frame.count == 0)
        return QString();
    QString shadow = !shadowsOn          ? QStringLiteral("off")
                     : s.shadow.count > 0 ? QStringLiteral("%1").arg(s.shadow.median, 0, 'f', 1)
                                          : QStringLiteral("cached");
    if (shadowsOn && s.shadow.count > 0 && s.shadow.count < s.frame.count)
        shadow += QCoreApplication::translate("FrameTimeHistory", " in %1 of %2").arg(s.shadow.count).arg(s.frame.count);
    return QCoreApplication::translate("FrameTimeHistory", "shadow %1 · lit %2 · frame %3 ms%4 · median of %5")
        .arg(shadow)
        .arg(s.lit.median, 0, 'f', 1)
        .arg(s.frame.median, 0, 'f', 1)
        .arg(cpuTime ? QCoreApplication::translate("FrameTimeHistory", " CPU") : QString())
        .arg(s.frame.count);
}

QString FrameTimeHistory::explanation(const Summary& s, bool shadowsOn)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("FrameTimeHistory", text); };
    if (s.frame.count == 0)
        return tr("No frames since the settings last changed.");
    if (!shadowsOn)
        return tr("%1 frames since the settings last changed; shadows are off.").arg(s.frame.count);
    if (s.shadow.count == 0)
        return tr("%1 frames since the settings last changed, each reusing the shadow map (nothing it depends on changed).").arg(s.frame.count);
    if (s.shadow.count == s.frame.count)
        return tr("%1 frames since the settings last changed, each redrawing the shadow map.").arg(s.frame.count);
    return tr("%1 of %2 frames since the settings last changed redrew the shadow map, at %3 ms a frame (median); the others "
              "reused it, at %4 ms. The shadow pass is the median of the first; the frame, of all.")
        .arg(s.shadow.count)
        .arg(s.frame.count)
        .arg(s.frameWithShadow.median, 0, 'f', 1)
        .arg(s.frameWithoutShadow.median, 0, 'f', 1);
}

} // namespace shadowlab
