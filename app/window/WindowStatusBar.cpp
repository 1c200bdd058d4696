#include "WindowStatusBar.h"

#include "ElidedLabel.h"
#include "FrameStats.h"
#include "FrameStatsText.h"
#include "Settings.h"
#include "SettingsSummary.h"

#include <QLabel>
#include <QMenu>
#include <QStyle>
#include <QToolButton>
#include <QWidgetAction>

namespace shadowlab {

WindowStatusBar::WindowStatusBar(QWidget* progress, QWidget* parent) : QStatusBar(parent)
{
    // As QMainWindow::statusBar() makes its own: the labels never widen the window.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_texelLabel = new QLabel;
    m_texelLabel->setObjectName(QStringLiteral("texelLabel"));
    m_timingLabel = new QLabel;
    m_timingLabel->setObjectName(QStringLiteral("timingLabel"));
    m_mapLabel = new QLabel;
    m_mapLabel->setObjectName(QStringLiteral("mapLabel"));
    m_mapLabel->setToolTip(tr("Shadow-map size, and the footprint of one of its texels in world units: the size of the blocks in a hard shadow"));
    m_texelLabel->setToolTip(tr("The shadow-map texel under the pointer in the depth-map view: its position, depth and distance from the light"));
    // Apart enough to read as three facts, not one run-on line.
    for (QLabel* label : {m_texelLabel, m_timingLabel, m_mapLabel})
        label->setContentsMargins(12, 0, 0, 0);
    addWidget(progress);
    // Messages on the left, over the room the permanent labels leave, ending in "…" with the
    // whole in the tooltip where they do not fit (a QStatusBar message is cut mid-word).
    m_messageLabel = new ElidedLabel;
    m_messageLabel->setObjectName(QStringLiteral("statusMessage"));
    addWidget(m_messageLabel, 1);
    m_warningsButton = new QToolButton;
    m_warningsButton->setObjectName(QStringLiteral("warningsButton"));
    m_warningsButton->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
    m_warningsButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_warningsButton->setAutoRaise(true);
    m_warningsButton->setPopupMode(QToolButton::InstantPopup);
    m_warningsButton->setMenu(new QMenu(m_warningsButton));
    m_warningsButton->setVisible(false);
    addPermanentWidget(m_warningsButton);
    m_messageTimer.setSingleShot(true);
    connect(&m_messageTimer, &QTimer::timeout, this, [this] { m_messageLabel->setFullText({}); });
    addPermanentWidget(m_texelLabel);
    addPermanentWidget(m_timingLabel);
    addPermanentWidget(m_mapLabel);
}

void WindowStatusBar::setMessage(const QString& text, int timeoutMs)
{
    m_messageLabel->setFullText(text);
    if (timeoutMs > 0)
        m_messageTimer.start(timeoutMs);
    else
        m_messageTimer.stop();
}

QString WindowStatusBar::message() const
{
    return m_messageLabel->fullText();
}

void WindowStatusBar::setWarnings(const QString& source, const QStringList& warnings)
{
    if (m_warnings.value(source) == warnings)
        return;
    if (warnings.isEmpty())
        m_warnings.remove(source);
    else
        m_warnings.insert(source, warnings);
    const QStringList all = this->warnings();
    m_warningsButton->setVisible(!all.isEmpty());
    m_warningsButton->setText(QString::number(all.size()));
    m_warningsButton->setToolTip(all.size() == 1 ? tr("1 warning: click to read it") : tr("%1 warnings: click to read them").arg(all.size()));
    QMenu* menu = m_warningsButton->menu();
    menu->clear();
    for (const QString& warning : all) {
        // Whole, on as many lines as it takes: a menu item is one line, so a wrapped label.
        auto* label = new QLabel(warning);
        label->setWordWrap(true);
        label->setMinimumWidth(420);
        label->setContentsMargins(8, 4, 8, 4);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        auto* item = new QWidgetAction(menu);
        item->setDefaultWidget(label);
        menu->addAction(item);
    }
}

QStringList WindowStatusBar::warnings() const
{
    QStringList all;
    for (const QStringList& list : m_warnings)
        all += list;
    return all;
}

void WindowStatusBar::setTexel(const QString& text)
{
    m_texelLabel->setText(text.isEmpty() ? text : tr("under pointer: %1").arg(text));
}

void WindowStatusBar::setTiming(const QString& text, const QString& toolTip)
{
    m_timingLabel->setText(text);
    m_timingLabel->setToolTip(toolTip);
}

void WindowStatusBar::showMap(const FrameStats& stats, const Settings& shown)
{
    // Short enough for the default window; the tooltip says it in full.
    const bool refitted = stats.lightFitted && stats.texelWorldSizeBeforeFit != stats.texelWorldSize;
    const QString footprint = tr("texel footprint %1 wu").arg(stats.texelWorldSize, 0, 'g', 3);
    const QString mapName = shown.shadow.virtualMap ? tr("virtual map, %1 pages").arg(stats.virtualPages.resident) : tr("map %1").arg(squareSize(shown.map.size));
    QString text = shown.shadow.enabled ? tr("%1 · %2").arg(mapName, footprint) : tr("no shadow map");
    if (const QString redrawn = redrawStatusText(stats); !redrawn.isEmpty())
        text += QStringLiteral(" · ") + redrawn;
    if (const QString cache = cacheStatusText(stats); shown.shadow.enabled && !cache.isEmpty())
        text += QStringLiteral(" · ") + cache;
    m_mapLabel->setText(text);
    QString mapTip = tr("Shadow-map size, and the footprint of one of its texels in world units: the size of the blocks in a hard shadow.");
    if (shown.shadow.enabled && refitted)
        mapTip += QLatin1Char(' ') + tr("Fitted to the scene: %1 wu a texel, against %2 wu with the volume as set.")
                                         .arg(stats.texelWorldSize, 0, 'g', 3)
                                         .arg(stats.texelWorldSizeBeforeFit, 0, 'g', 3);
    if (const QString warp = warpStatusText(stats); shown.shadow.enabled && !warp.isEmpty())
        mapTip += QLatin1Char(' ') + warp + QLatin1Char('.');
    if (const QString pages = virtualMapStatusText(stats); shown.shadow.enabled && !pages.isEmpty())
        mapTip += QLatin1Char(' ') + pages + QLatin1Char('.');
    m_mapLabel->setToolTip(mapTip);
}

} // namespace shadowlab
