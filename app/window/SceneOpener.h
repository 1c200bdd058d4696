#pragma once

#include "SceneFileError.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <atomic>
#include <memory>

class QThread;

namespace shadowlab {

// Reads a model or scene file in the background (loadSceneFile() on a thread of its own, the
// parsing itself in the import worker), so the window stays usable while it loads: progress
// as it comes, cancel at any time. One file at a time; opening another cancels the first.
// When it is done the scene is in the loader's cache, so the window applies it at once.
class SceneOpener : public QObject {
    Q_OBJECT

public:
    explicit SceneOpener(QObject* parent = nullptr);
    ~SceneOpener() override;   // cancels and waits for the worker (milliseconds)

    // Starts reading `path`; one still being read is cancelled (its finished() comes later,
    // from the event loop).
    void open(const QString& path);
    void cancel();
    bool isBusy() const { return m_thread != nullptr; }
    const QString& path() const { return m_path; }
    // The import limit that stopped the file of the last finished(), if one did.
    SceneFileError::Limit lastLimit() const { return m_lastLimit; }

signals:
    void started(const QString& path);
    void progressed(double fraction);
    // `error` is empty when the scene is ready; `cancelled` when cancel() stopped it.
    void finished(const QString& path, const QString& error, bool cancelled);

private:
    struct Job {
        std::atomic<bool> cancel = false;
        std::atomic<double> progress = 0.0;
        QString error;          // written by the thread before it ends, read after
        SceneFileError::Limit limit = SceneFileError::Limit::None;
        bool cancelled = false;
    };
    void stopThread();   // cancels and waits; says nothing

    QThread* m_thread = nullptr;
    std::shared_ptr<Job> m_job;
    QString m_path;
    QTimer m_progressTimer;
    SceneFileError::Limit m_lastLimit = SceneFileError::Limit::None;
};

} // namespace shadowlab
