#pragma once

#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <memory>

namespace shadowlab {

// Keeps the explorer's session (both sides' settings, compare mode, the scene, the layout) on
// disk as it changes, so that a crash or a kill loses at most the last second. Saves go through
// QSettings, which writes a new file and renames it over the old one (an atomic write), at most
// once a second. A marker says whether the session is running: one still set at start, with no
// other explorer holding the session's lock, means the last session did not end cleanly.
class SessionAutosave : public QObject {
    Q_OBJECT

public:
    static constexpr int kDelayMs = 1000;

    // `save` writes the state into QSettings; this class syncs it to disk.
    explicit SessionAutosave(std::function<void()> save, QObject* parent = nullptr);

    // Sets the running marker; returns whether it was already set (the last session crashed
    // or was killed). What was being opened then is openingAtStart().
    bool begin();
    const QString& openingAtStart() const { return m_openingAtStart; }
    // Something changed: saved within kDelayMs, however often this is called.
    void changed();
    // A scene being read (empty when done), kept on disk at once: after a crash it is not
    // reopened by itself.
    void setOpening(const QString& path);
    // A clean end: saved now, marker cleared.
    void end();
    void flush();

private:
    std::function<void()> m_save;
    QTimer m_timer;
    QString m_openingAtStart;
    std::unique_ptr<QLockFile> m_lock;  // held while running: a second explorer is not a crash
};

} // namespace shadowlab
