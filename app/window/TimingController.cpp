#include "TimingController.h"

#include "AccuracyMetricsPanel.h"
#include "CompareController.h"
#include "Renderer.h"
#include "SceneView.h"

#include <QAction>

namespace shadowlab {

TimingController::TimingController(const CompareController& sides, std::array<SceneView*, 2> views, QObject* parent)
    : QObject(parent), m_sides(sides), m_views(views)
{
}

QAction* TimingController::createMeasureAction(QObject* owner)
{
    m_measureAction = new QAction(tr("&Measure 100 Frames"), owner);
    m_measureAction->setObjectName(QStringLiteral("measureAction"));
    m_measureAction->setToolTip(tr("Render the selected side 100 times, the shadow pass included, and show the medians and spread"));
    connect(m_measureAction, &QAction::triggered, this, [this] { measure(kMeasuredFrames); });
    return m_measureAction;
}

void TimingController::measure(int count)
{
    if (m_measureAction)
        m_measureAction->setEnabled(false);
    emit message(tr("Measuring %1 frames…").arg(count), 0);
    const std::size_t selected = m_sides.selected();
    for (std::size_t i = 0; i < 2; ++i) {
        if (i == selected || m_sides.isOn()) {
            m_history[i].clear();
            m_history[i].setCapacity(count);
        }
    }
    m_measureLeft = count;
    m_views[selected]->redrawForMeasurement();
    if (m_sides.isOn())
        m_views[1 - selected]->redrawForMeasurement();
}

void TimingController::record(std::size_t side, bool animated)
{
    const Renderer* renderer = m_views[side]->renderer();
    if (!renderer || !m_views[side]->renderedSettings())
        return;
    // One window of frame times per settings state: a frame of other settings says nothing
    // about these. The camera is the view's, and an animated light moves every frame.
    Settings state = *m_views[side]->renderedSettings();
    state.camera = {};
    if (animated)
        state.light.position = {};
    if (m_historyState[side] != state) {
        m_history[side].clear();
        m_historyState[side] = state;
    }
    m_history[side].add(renderer->lastFrame());
    emit frameRecorded();
    if (m_measureLeft > 0) {
        // Each side redraws itself (shadow pass included) until the selected one has its frames.
        const bool selected = side == m_sides.selected();
        if (selected && --m_measureLeft == 0) {
            // Short in the status bar; every pass with its spread stays in the accuracy dock's cost table.
            if (m_measureAction)
                m_measureAction->setEnabled(true);
            const FrameTimeHistory::Summary s = m_history[side].summary();
            emit message(tr("%1 frames: %2 ms a frame (p10–p90 %3–%4) — see Accuracy → Cost")
                             .arg(s.frame.count)
                             .arg(s.frame.median, 0, 'f', 1)
                             .arg(s.frame.p10, 0, 'f', 1)
                             .arg(s.frame.p90, 0, 'f', 1),
                         0);
        } else if (selected || m_sides.isOn())
            m_views[side]->redrawForMeasurement();
    }
}

std::vector<FrameTimeHistory::Summary> TimingController::summaries() const
{
    std::vector<FrameTimeHistory::Summary> sides{m_history[0].summary()};
    if (m_sides.isOn())
        sides.push_back(m_history[1].summary());
    return sides;
}

bool TimingController::cpuTime() const
{
    const Renderer* renderer = m_views[0]->renderer();
    return renderer && isSoftwareRenderer(renderer->rendererString());
}

QString TimingController::text(std::size_t side) const
{
    const Renderer* renderer = m_views[side]->renderer();
    if (!renderer)
        return QString();
    const std::optional<Settings>& shown = m_views[side]->renderedSettings();
    return FrameTimeHistory::text(m_history[side].summary(), isSoftwareRenderer(renderer->rendererString()), !shown || shown->shadow.enabled);
}

QString TimingController::statusText() const
{
    if (!m_sides.isOn())
        return text(m_sides.selected());
    // Both sides' frame and what B costs more (or less) than A, short enough for the default
    // window: the passes of each are in the tooltip and in the accuracy dock's cost table.
    const FrameTimeHistory::Summary a = m_history[0].summary(), b = m_history[1].summary();
    if (a.frame.count == 0 || b.frame.count == 0)
        return QString();
    // As the accuracy dock: no difference until each side has frames enough to tell one.
    constexpr int enough = AccuracyMetricsPanel::kFramesToCompare;
    if (a.frame.count < enough || b.frame.count < enough)
        return tr("frame A: %1 · B: %2 · measuring (%3 and %4 of %5 frames)")
            .arg(a.frame.median, 0, 'f', 1)
            .arg(b.frame.median, 0, 'f', 1)
            .arg(a.frame.count)
            .arg(b.frame.count)
            .arg(enough);
    return tr("frame A: %1 · B: %2 · B − A: %3 ms%4 · medians")
        .arg(a.frame.median, 0, 'f', 1)
        .arg(b.frame.median, 0, 'f', 1)
        .arg(b.frame.median - a.frame.median, 0, 'f', 1)
        .arg(cpuTime() ? tr(" CPU") : QString());
}

QString TimingController::toolTip() const
{
    const QString about = tr("Medians over the last frames of the wall time of the shadow pass (over the frames that ran it; \"cached\" "
                             "when the light, the casters and the map did not change), the lit pass and the whole frame, each between "
                             "glFinish calls; on a software renderer (llvmpipe) that is CPU time (\"CPU\"). View → Measure 100 "
                             "Frames times the pass on every frame.");
    const auto side = [this](std::size_t side) {
        const std::optional<Settings>& shown = m_views[side]->renderedSettings();
        return FrameTimeHistory::explanation(m_history[side].summary(), !shown || shown->shadow.enabled);
    };
    if (!m_sides.isOn())
        return tr("%1\n\n%2").arg(side(0), about);
    return tr("Side A: %1 %2\nSide B: %3 %4\n\n%5").arg(text(0), side(0), text(1), side(1), about);
}

} // namespace shadowlab
