#include "SceneOpener.h"

#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SettingsKeys.h"

#include <QThread>

namespace shadowlab {

SceneOpener::SceneOpener(QObject* parent) : QObject(parent)
{
    m_progressTimer.setInterval(100);
    connect(&m_progressTimer, &QTimer::timeout, this, [this] {
        if (m_job)
            emit progressed(m_job->progress.load());
    });
}

SceneOpener::~SceneOpener()
{
    stopThread();
}

void SceneOpener::open(const QString& path)
{
    // The one it replaces is said to be cancelled once this one is under way, from the event
    // loop: a slot that opens a file in answer then does not re-enter this function.
    const QString replaced = m_thread ? m_path : QString();
    stopThread();
    if (!replaced.isEmpty())
        QMetaObject::invokeMethod(this, [this, replaced] { emit finished(replaced, QString(), true); }, Qt::QueuedConnection);
    m_path = path;
    auto job = std::make_shared<Job>();
    m_job = job;
    m_thread = QThread::create([job, path] {
        ImportControl control;
        control.cancel = &job->cancel;
        control.progress = [job](double fraction) { job->progress = fraction; };
        try {
            Settings probe;
            applySetting(probe, QStringLiteral("scene"), path);  // the same checks as every other way in
            if (!isPresetName(probe.scene))
                loadSceneFile(probe.scene, control);
        } catch (const ImportCancelled&) {
            job->cancelled = true;
        } catch (const SceneFileError& e) {
            job->error = QString::fromUtf8(e.what());
            job->limit = e.limit();
        } catch (const SettingsError& e) {
            job->error = QString::fromUtf8(e.what());
        } catch (const std::exception& e) {
            job->error = QStringLiteral("'%1' cannot be read: %2").arg(path, QString::fromUtf8(e.what()));
        }
    });
    m_thread->setObjectName(QStringLiteral("scene opener"));
    connect(m_thread, &QThread::finished, this, [this, job, thread = m_thread] {
        if (job != m_job)
            return;     // a job already stopped by stopThread()
        thread->deleteLater();
        m_thread = nullptr;
        m_job.reset();
        m_progressTimer.stop();
        m_lastLimit = job->limit;
        emit finished(m_path, job->error, job->cancelled);
    });
    m_thread->start();
    m_progressTimer.start();
    emit started(path);
    emit progressed(0.0);
}

void SceneOpener::cancel()
{
    if (m_job)
        m_job->cancel = true;   // the worker is killed within ImportControl's poll interval
}

void SceneOpener::stopThread()
{
    if (!m_thread)
        return;
    const std::shared_ptr<Job> job = std::move(m_job);
    job->cancel = true;
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_progressTimer.stop();
}

} // namespace shadowlab
