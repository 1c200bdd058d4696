#pragma once

#include <QMap>
#include <QStatusBar>
#include <QStringList>
#include <QTimer>

class QLabel;
class QToolButton;

namespace shadowlab {

class ElidedLabel;
struct FrameStats;
struct Settings;

// The explorer's status bar: on the left what is being opened (`progress`) and the messages,
// over the room the permanent labels leave; on the right three facts: the shadow-map texel under
// the pointer, the frame times, and the map's size with the footprint of one of its texels.
class WindowStatusBar : public QStatusBar {
    Q_OBJECT

public:
    explicit WindowStatusBar(QWidget* progress, QWidget* parent = nullptr);

    // Shown for `timeoutMs` (0: until the next message).
    void setMessage(const QString& text, int timeoutMs);
    // The message, whole (on screen it may end in "…"); empty when there is none.
    QString message() const;
    // The texel under the pointer in the depth-map view, empty when there is none.
    void setTexel(const QString& text);
    void setTiming(const QString& text, const QString& toolTip);
    // The map of the frame `stats` rendered with `shown`.
    void showMap(const FrameStats& stats, const Settings& shown);
    // The warnings that `source` ("fit", "import") stands by now, in place of its earlier ones:
    // a button beside the messages counts them all and lists them whole, so none is lost behind
    // another or cut off.
    void setWarnings(const QString& source, const QStringList& warnings);
    QStringList warnings() const;

private:
    QLabel* m_texelLabel = nullptr;
    QLabel* m_timingLabel = nullptr;
    QLabel* m_mapLabel = nullptr;
    ElidedLabel* m_messageLabel = nullptr;
    QToolButton* m_warningsButton = nullptr;
    QMap<QString, QStringList> m_warnings;  // by source
    QTimer m_messageTimer;              // clears a message after its time
};

} // namespace shadowlab
