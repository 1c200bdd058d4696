#include "SceneFileWatcher.h"

#include "SceneNames.h"

#include <QFileInfo>

namespace shadowlab {

SceneFileWatcher::SceneFileWatcher(QObject* parent) : QObject(parent)
{
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &SceneFileWatcher::noticed);
    connect(&m_settle, &QTimer::timeout, this, &SceneFileWatcher::settled);
}

void SceneFileWatcher::watch(const QStringList& scenes)
{
    QStringList files;
    for (const QString& scene : scenes) {
        if (!scene.isEmpty() && !isPresetName(scene) && !files.contains(QFileInfo(scene).absoluteFilePath()))
            files << QFileInfo(scene).absoluteFilePath();
    }
    if (files != m_watched) {
        if (!m_watcher.files().isEmpty())
            m_watcher.removePaths(m_watcher.files());
        m_watched = files;
    }
    // Again where a file was missing when it was first watched, or for longer than its tries.
    for (const QString& file : std::as_const(m_watched)) {
        if (!m_watcher.files().contains(file) && QFileInfo::exists(file))
            m_watcher.addPath(file);
    }
    for (auto it = m_changed.begin(); it != m_changed.end();)
        it = m_watched.contains(it.key()) ? std::next(it) : m_changed.erase(it);
}

void SceneFileWatcher::noticed(const QString& path)
{
    m_changed.insert(path, 0);
    m_settle.start();   // again: the file is still being written
}

void SceneFileWatcher::settled()
{
    const QHash<QString, int> noticed = std::exchange(m_changed, {});
    for (auto it = noticed.begin(); it != noticed.end(); ++it) {
        const QString& path = it.key();
        if (!m_watched.contains(path))
            continue;
        if (!QFileInfo::exists(path)) {
            if (it.value() < kMissingTries) {
                m_changed.insert(path, it.value() + 1);
                m_settle.start();
            }
            continue;
        }
        // A file renamed over the old one is a new file: watched again.
        if (!m_watcher.files().contains(path))
            m_watcher.addPath(path);
        emit changed(path);
    }
}

} // namespace shadowlab
