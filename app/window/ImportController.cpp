#include "ImportController.h"

#include "CompareController.h"
#include "ImportLimits.h"
#include "ModelImporter.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SceneOpener.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>

namespace shadowlab {

ImportController::ImportController(QWidget* window, CompareController& sides, Apply apply)
    : QObject(window), m_window(window), m_sides(sides), m_apply(std::move(apply))
{
    m_opener = new SceneOpener(this);
    connect(m_opener, &SceneOpener::finished, this, &ImportController::finished);
}

QString ImportController::open(const QString& path)
{
    QStringList warnings;
    try {
        Settings probe;
        applySetting(probe, QStringLiteral("scene"), path);
        const Settings loaded = presetSettings(probe.scene);   // imports (cached) or throws
        if (!isPresetName(loaded.scene))
            warnings = loadSceneFile(loaded.scene)->warnings;
        m_apply(movedToScene(m_sides.selectedSettings(), loaded), tr("Open %1").arg(QFileInfo(path).fileName()));
    } catch (const SettingsError& e) {
        return QString::fromUtf8(e.what());
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_recentScenes.removeAll(absolute);
    m_recentScenes.prepend(absolute);
    while (m_recentScenes.size() > kMaxRecentScenes)
        m_recentScenes.removeLast();
    updateRecentMenu();
    QStringList named;
    for (const QString& warning : std::as_const(warnings))
        named << tr("%1: %2").arg(QFileInfo(path).fileName(), warning);
    emit warningsFound(named);
    if (!named.isEmpty())
        emit message(named.size() == 1 ? named.front() : tr("%1 (and %n more: the warnings button lists them)", nullptr, int(named.size() - 1)).arg(named.front()), 15000);
    return QString();
}

void ImportController::openInBackground(const QString& path)
{
    m_pendingRestore = {};      // the user's choice wins over a restore still reading
    m_restoreQueue.clear();
    m_opener->open(path);
}

void ImportController::openInteractively()
{
    QStringList patterns;
    for (const QString& suffix : modelSuffixes())
        patterns << QStringLiteral("*.") + suffix;
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Open Scene"), m_recentScenes.isEmpty() ? QDir::homePath() : QFileInfo(m_recentScenes.first()).path(),
        tr("Models and scene files (%1 *.json);;All files (*)").arg(patterns.join(QLatin1Char(' '))));
    if (!path.isEmpty())
        openInBackground(path);
}

void ImportController::cancel()
{
    m_opener->cancel();
}

void ImportController::dragEnter(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().size() == 1 && event->mimeData()->urls().first().isLocalFile())
        event->acceptProposedAction();
}

void ImportController::drop(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !urls.first().isLocalFile())
        return;
    event->acceptProposedAction();
    openInBackground(urls.first().toLocalFile());
}

void ImportController::setRecentScenes(const QStringList& paths)
{
    m_recentScenes = paths;
    updateRecentMenu();
}

void ImportController::setRecentMenu(QMenu* menu)
{
    m_recentMenu = menu;
    updateRecentMenu();
}

void ImportController::updateRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    for (const QString& path : m_recentScenes)
        m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] { openInBackground(path); })->setToolTip(path);
    m_recentMenu->setEnabled(!m_recentScenes.isEmpty());
}

QWidget* ImportController::createProgressBox()
{
    // While a file is read in the background: what, how far, and a way to stop it.
    m_openBox = new QWidget;
    m_openBox->setObjectName(QStringLiteral("openSceneProgress"));
    auto* openLayout = new QHBoxLayout(m_openBox);
    openLayout->setContentsMargins(0, 0, 0, 0);
    m_openLabel = new QLabel;
    m_openProgress = new QProgressBar;
    m_openProgress->setRange(0, 100);
    m_openProgress->setMaximumWidth(140);
    auto* cancel = new QPushButton(tr("Cancel"));
    cancel->setObjectName(QStringLiteral("cancelOpenButton"));
    cancel->setToolTip(tr("Stop reading the file; the current scene stays (Esc)"));
    cancel->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(cancel, &QPushButton::clicked, m_opener, &SceneOpener::cancel);
    openLayout->addWidget(m_openLabel);
    openLayout->addWidget(m_openProgress);
    openLayout->addWidget(cancel);
    m_openBox->setVisible(false);
    connect(m_opener, &SceneOpener::progressed, m_openProgress, [this](double fraction) { m_openProgress->setValue(int(fraction * 100.0 + 0.5)); });
    connect(m_opener, &SceneOpener::started, this, [this](const QString& path) {
        m_openLabel->setText(tr("Opening %1…").arg(QFileInfo(path).fileName()));
        m_openLabel->setToolTip(path);
        m_openProgress->setValue(0);
        m_openBox->setVisible(true);
        // A file read again is the one drawn already: no suspect for the session's recovery.
        if (path != m_reloading)
            emit readingStarted(QFileInfo(path).absoluteFilePath());
    });
    return m_openBox;
}

bool ImportController::userOpening() const
{
    return m_opener->isBusy() && !m_restoreQueue.contains(m_opener->path()) && m_opener->path() != m_reloading;
}

void ImportController::queueRestore(std::size_t side, const Settings& settings)
{
    m_pendingRestore[side] = settings;
    if (!m_restoreQueue.contains(settings.scene))
        m_restoreQueue << settings.scene;
}

void ImportController::reload(const QString& path)
{
    // One read at a time: a change noticed while the opener reads (another file, or this one
    // still being written) is read once it is done.
    if (!m_reloadQueue.contains(path))
        m_reloadQueue << path;
    startReload();
}

void ImportController::startReload()
{
    if (m_opener->isBusy() || m_reloadQueue.isEmpty())
        return;
    m_reloading = m_reloadQueue.takeFirst();
    m_opener->open(m_reloading);
}

void ImportController::finishReload(const QString& path, const QString& error, bool cancelled)
{
    m_reloading.clear();
    const QString name = QFileInfo(path).fileName();
    if (cancelled)
        emit message(tr("%1 changed on disk: reading it again was cancelled").arg(name), 8000);
    else if (!error.isEmpty())
        emit message(tr("%1 changed on disk and cannot be read now: %2 — the last good version stays").arg(name, error), 15000);
    else {
        emit message(tr("%1 changed on disk: read again").arg(name), 5000);
        emit sceneReloaded(path);
    }
}

void ImportController::startRestore()
{
    if (!m_restoreQueue.isEmpty())
        m_opener->open(m_restoreQueue.first());
}

void ImportController::showOpenError(const QString& path, const QString& error, SceneFileError::Limit limit)
{
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), tr("%1\n\nThe current scene stays.").arg(error),
                                QMessageBox::Ok, m_window);
    box->setObjectName(QStringLiteral("openErrorBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    // A file that is only large opens with a higher limit: offered here, in the box that refused it.
    ImportLimits raised = importLimits();
    QString offer;
    if (limit == SceneFileError::Limit::Time && raised.timeSeconds < 3600.0) {
        raised.timeSeconds = std::min(3600.0, std::max(60.0, raised.timeSeconds * 4.0));
        offer = tr("Try Again with %1 s").arg(raised.timeSeconds);
    } else if (limit == SceneFileError::Limit::Memory && raised.memoryMiB < 65536) {
        raised.memoryMiB = std::min(65536, raised.memoryMiB * 2);
        offer = tr("Try Again with %1 MiB").arg(raised.memoryMiB);
    }
    if (!offer.isEmpty()) {
        QPushButton* retry = box->addButton(offer, QMessageBox::AcceptRole);
        retry->setObjectName(QStringLiteral("retryButton"));
        box->setInformativeText(tr("File > Import Limits… sets both limits for the rest of this run."));
        connect(retry, &QPushButton::clicked, this, [this, path, raised] {
            setImportLimits(raised);
            openInBackground(path);
        });
    }
    box->open();
}

void ImportController::editLimits()
{
    QDialog dialog(m_window);
    dialog.setObjectName(QStringLiteral("importLimitsDialog"));
    dialog.setWindowTitle(tr("Import Limits"));
    auto* form = new QFormLayout(&dialog);
    const ImportLimits current = importLimits();
    auto* seconds = new QDoubleSpinBox;
    seconds->setObjectName(QStringLiteral("importTimeLimit"));
    seconds->setRange(1.0, 3600.0);
    seconds->setDecimals(0);
    seconds->setSuffix(tr(" s"));
    seconds->setValue(current.timeSeconds);
    seconds->setToolTip(tr("How long the importer may read one model file before it is stopped (a damaged file can take forever)"));
    auto* memory = new QSpinBox;
    memory->setObjectName(QStringLiteral("importMemoryLimit"));
    memory->setRange(256, 65536);
    memory->setSingleStep(1024);
    memory->setSuffix(tr(" MiB"));
    memory->setValue(current.memoryMiB);
    memory->setToolTip(tr("How much memory the importer may use for one model file before it is stopped"));
    form->addRow(tr("Time per file:"), seconds);
    form->addRow(tr("Memory per file:"), memory);
    auto* note = new QLabel(tr("For the rest of this run. A file that is only large opens with more; a damaged one is stopped sooner with less."));
    note->setWordWrap(true);
    form->addRow(note);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ImportLimits limits = current;
    limits.timeSeconds = seconds->value();
    limits.memoryMiB = memory->value();
    setImportLimits(limits);    // the fields' ranges are the limits' own: nothing to refuse
    emit message(tr("Import limits: %1 s and %2 MiB per file").arg(limits.timeSeconds).arg(limits.memoryMiB), 8000);
}

void ImportController::finished(const QString& path, const QString& error, bool cancelled)
{
    m_openBox->setVisible(false);
    emit readingEnded();
    if (!m_reloading.isEmpty() && path == m_reloading) {
        finishReload(path, error, cancelled);
        startReload();
        return;
    }
    // Changes noticed while another file was read are read once it is handled.
    QTimer::singleShot(0, this, &ImportController::startReload);
    if (m_restoreQueue.contains(path)) {
        finishRestore(path, error, cancelled);
        return;
    }
    if (cancelled) {
        emit message(tr("Cancelled: %1 not opened").arg(QFileInfo(path).fileName()), 8000);
        return;
    }
    const QString failure = error.isEmpty() ? open(path) : error;
    if (!failure.isEmpty()) {
        showOpenError(path, failure, error.isEmpty() ? SceneFileError::Limit::None : m_opener->lastLimit());
        return;
    }
    // Suspect until its first frame is drawn: a crash before that does not reopen it.
    emit sceneApplied(m_sides.selectedSettings().scene, true);
    emit fileOpened(path);
}

void ImportController::finishRestore(const QString& path, const QString& error, bool cancelled)
{
    // A scene of the restored session: its sides take their saved settings.
    m_restoreQueue.removeAll(path);
    for (std::size_t i = 0; i < 2; ++i) {
        if (!m_pendingRestore[i] || m_pendingRestore[i]->scene != path)
            continue;
        if (error.isEmpty() && !cancelled) {
            m_sides.settings(i) = *m_pendingRestore[i];
            m_sides.settings(1 - i).camera = m_sides.settings(i).camera;
            emit sceneApplied(path, false);     // suspect until drawn, as a scene the user opens
        }
        m_pendingRestore[i].reset();
    }
    emit restoredSidesChanged();
    if (!error.isEmpty())
        emit message(tr("The last session's scene cannot be read: %1 — showing the default scene").arg(error), 15000);
    startRestore();
}

} // namespace shadowlab
