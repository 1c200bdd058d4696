#pragma once

#include <QFileSystemWatcher>
#include <QObject>
#include <QHash>
#include <QStringList>
#include <QTimer>

namespace shadowlab {

// The model and scene files the window shows, watched on disk: changed() once a file that
// changed has been left alone for a moment (an editor saves in steps, or writes a new file and
// renames it over the old one, which a plain watch loses).
class SceneFileWatcher : public QObject {
    Q_OBJECT

public:
    explicit SceneFileWatcher(QObject* parent = nullptr);

    // The scenes shown now (settings.scene of each side): the files among them are watched, the
    // rest no longer.
    void watch(const QStringList& scenes);

    static constexpr int kSettleMs = 300;
    // A file gone when it settles (removed, to be written anew) is looked for this many times more.
    static constexpr int kMissingTries = 20;

signals:
    void changed(const QString& path);

private:
    void noticed(const QString& path);
    void settled();

    QFileSystemWatcher m_watcher;
    QStringList m_watched;          // absolute paths, whether the file exists now or not
    QHash<QString, int> m_changed;  // noticed, waiting to settle: how many times it was missing since
    QTimer m_settle;
};

} // namespace shadowlab
