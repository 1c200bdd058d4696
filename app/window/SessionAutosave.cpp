#include "SessionAutosave.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace shadowlab {

namespace {

const QString kRunning = QStringLiteral("session/running");
const QString kOpening = QStringLiteral("session/opening");

} // namespace

SessionAutosave::SessionAutosave(std::function<void()> save, QObject* parent) : QObject(parent), m_save(std::move(save))
{
    // Not restarted by later changes: a steady stream of them (a slider dragged) is still saved
    // every second.
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDelayMs);
    connect(&m_timer, &QTimer::timeout, this, &SessionAutosave::flush);
}

bool SessionAutosave::begin()
{
    QSettings store;
    // A stale lock (its process gone) is taken over; a live one is another explorer running.
    const QString folder = QFileInfo(store.fileName()).absolutePath();
    QDir().mkpath(folder);
    m_lock = std::make_unique<QLockFile>(QDir(folder).filePath(QStringLiteral("session.lock")));
    const bool alone = m_lock->tryLock(0);
    const bool crashed = alone && store.value(kRunning, false).toBool();
    m_openingAtStart = crashed ? store.value(kOpening).toString() : QString();
    store.setValue(kRunning, true);
    store.remove(kOpening);
    store.sync();
    return crashed;
}

void SessionAutosave::changed()
{
    if (!m_timer.isActive())
        m_timer.start();
}

void SessionAutosave::setOpening(const QString& path)
{
    QSettings store;
    if (path.isEmpty())
        store.remove(kOpening);
    else
        store.setValue(kOpening, path);
    store.sync();
}

void SessionAutosave::flush()
{
    m_timer.stop();
    m_save();
    QSettings().sync();
}

void SessionAutosave::end()
{
    flush();
    QSettings store;
    store.setValue(kRunning, false);
    store.remove(kOpening);
    store.sync();
    if (m_lock)
        m_lock->unlock();
}

} // namespace shadowlab
