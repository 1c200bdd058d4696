#include "PersistenceController.h"

#include "CompareController.h"
#include "ImportController.h"
#include "MainWindow.h"
#include "OutputFile.h"
#include "SceneLibrary.h"
#include "SessionAutosave.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QTimer>

namespace shadowlab {

namespace {

const char* const kSideNames[] = {"A", "B"};

QString settingsAsText(const Settings& settings)
{
    return QString::fromUtf8(QJsonDocument(settingsToJson(settings)).toJson(QJsonDocument::Compact));
}

// Stored settings on top of their scene's preset; nullopt when they no longer parse or validate
// (a key renamed between versions), so a bad file never stops the window from opening.
std::optional<Settings> settingsFromText(const QString& text)
{
    const QJsonObject object = QJsonDocument::fromJson(text.toUtf8()).object();
    if (object.isEmpty())
        return std::nullopt;
    try {
        // Every key is stored, so a file scene needs no base from its bounds, and is not read here.
        const QString scene = object.value(QStringLiteral("scene")).toString(QStringLiteral("seed"));
        Settings settings = settingsFromJson(object, isPresetName(scene) ? presetSettings(scene) : Settings{});
        ensureValid(settings);
        return settings;
    } catch (const SettingsError&) {
        return std::nullopt;
    }
}

} // namespace

PersistenceController::PersistenceController(MainWindow& window, CompareController& sides, ImportController& import, bool enabled)
    : QObject(&window), m_window(window), m_sides(sides), m_import(import), m_enabled(enabled)
{
    m_autosave = new SessionAutosave([this] { save(); }, this);
    // A file being read, and one applied but not drawn yet, are said on disk at once.
    connect(&import, &ImportController::readingStarted, this, &PersistenceController::setOpening);
    connect(&import, &ImportController::readingEnded, this, [this] { setOpening({}); });
    connect(&import, &ImportController::sceneApplied, this, &PersistenceController::setSuspect);
}

void PersistenceController::start(QSplitter* splitter, QAction* lightVolume, const std::vector<QDockWidget*>& docks)
{
    m_splitter = splitter;
    m_lightVolume = lightVolume;
    if (!m_enabled)
        return;
    const bool crashed = m_autosave->begin();
    restoreLayout();
    if (crashed) {
        m_hold = true;
        QTimer::singleShot(0, this, [this, opening = m_autosave->openingAtStart()] { offerRestore(opening); });
    } else {
        restoreSession(savedSession());
    }
    // The layout is part of the session too.
    connect(m_splitter, &QSplitter::splitterMoved, this, &PersistenceController::changed);
    for (QDockWidget* dock : docks) {
        connect(dock, &QDockWidget::dockLocationChanged, this, &PersistenceController::changed);
        connect(dock, &QDockWidget::topLevelChanged, this, &PersistenceController::changed);
        connect(dock, &QDockWidget::visibilityChanged, this, &PersistenceController::changed);
    }
}

void PersistenceController::changed()
{
    if (m_enabled && !m_hold)
        m_autosave->changed();
}

void PersistenceController::setOpening(const QString& path)
{
    if (m_enabled)
        m_autosave->setOpening(path);
}

void PersistenceController::setSuspect(const QString& scene, bool flush)
{
    if (!m_enabled)
        return;
    m_openingScene = scene;
    m_autosave->setOpening(scene);
    if (flush)
        m_autosave->flush();
}

void PersistenceController::drawn(const QString& scene)
{
    if (!m_openingScene.isEmpty() && scene == m_openingScene) {
        m_openingScene.clear();     // drawn: no longer a suspect after a crash
        m_autosave->setOpening({});
    }
}

void PersistenceController::end()
{
    if (m_enabled)
        m_autosave->end();
}

void PersistenceController::restoreLayout()
{
    QSettings store;
    if (const QByteArray geometry = store.value(QStringLiteral("window/geometry")).toByteArray(); !geometry.isEmpty())
        m_window.restoreGeometry(geometry);
    if (const QByteArray state = store.value(QStringLiteral("window/state")).toByteArray(); !state.isEmpty())
        m_window.restoreState(state);
    if (const QByteArray splitter = store.value(QStringLiteral("window/splitter")).toByteArray(); !splitter.isEmpty())
        m_splitter->restoreState(splitter);
    m_import.setRecentScenes(store.value(QStringLiteral("scenes/recent")).toStringList());
    m_lightVolume->setChecked(store.value(QStringLiteral("view/lightVolume"), true).toBool());
    m_lastFolder = store.value(QStringLiteral("view/screenshotFolder"), m_lastFolder).toString();
}

QVariantMap PersistenceController::savedSession() const
{
    QSettings store;
    QVariantMap session;
    for (const QString& key : {QStringLiteral("settings/A"), QStringLiteral("settings/B"), QStringLiteral("view/compare"), QStringLiteral("view/selected")})
        session.insert(key, store.value(key));
    return session;
}

void PersistenceController::restoreSession(const QVariantMap& session, const QString& skipScene)
{
    const bool userOpening = m_import.userOpening();
    for (std::size_t i = 0; i < 2; ++i) {
        const std::optional<Settings> settings = settingsFromText(session.value(QStringLiteral("settings/%1").arg(QLatin1String(kSideNames[i]))).toString());
        if (!settings || (!skipScene.isEmpty() && settings->scene == skipScene))
            continue;
        if (isPresetName(settings->scene))
            m_sides.settings(i) = *settings;
        else if (!userOpening)
            m_import.queueRestore(i, *settings);
    }
    m_sides.settings(1).camera = m_sides.settings(0).camera;
    m_window.setCompareMode(session.value(QStringLiteral("view/compare"), false).toBool());
    m_sides.select(session.value(QStringLiteral("view/selected")).toString() == u"B" ? 1 : 0);
    m_import.startRestore();
}

void PersistenceController::offerRestore(const QString& openingAtCrash)
{
    auto* box = new QMessageBox(&m_window);
    box->setObjectName(QStringLiteral("restoreSessionBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setIcon(QMessageBox::Question);
    box->setWindowTitle(tr("Restore Session"));
    QString text = tr("ShadowLab did not close properly last time: it crashed or was stopped.\n\nRestore that session? Both sides' "
                      "settings, compare mode and the scene come back as they were a second before.");
    if (!openingAtCrash.isEmpty())
        text += tr("\n\n%1 was being opened then; it is not reopened. Open it again from File → Open Recent if you trust it.")
                    .arg(QFileInfo(openingAtCrash).fileName());
    box->setText(text);
    QPushButton* restore = box->addButton(tr("Restore Session"), QMessageBox::AcceptRole);
    restore->setObjectName(QStringLiteral("restoreSessionButton"));
    box->addButton(tr("Start Fresh"), QMessageBox::RejectRole)->setObjectName(QStringLiteral("startFreshButton"));
    box->setDefaultButton(restore);
    // Read now: until the question is answered nothing is saved over it.
    connect(box, &QMessageBox::buttonClicked, this, [this, restore, openingAtCrash, session = savedSession()](QAbstractButton* button) {
        m_hold = false;
        if (button == restore) {
            restoreSession(session, openingAtCrash);
            emit sessionRestored();
        }
        changed();
    });
    box->open();
}

void PersistenceController::save() const
{
    QSettings store;
    store.setValue(QStringLiteral("window/geometry"), m_window.saveGeometry());
    store.setValue(QStringLiteral("window/state"), m_window.saveState());
    store.setValue(QStringLiteral("window/splitter"), m_splitter->saveState());
    store.setValue(QStringLiteral("scenes/recent"), m_import.recentScenes());
    for (std::size_t i = 0; i < 2; ++i)
        store.setValue(QStringLiteral("settings/%1").arg(QLatin1String(kSideNames[i])), settingsAsText(m_import.pendingRestore(i).value_or(m_sides.settings(i))));
    store.setValue(QStringLiteral("view/lightVolume"), m_lightVolume->isChecked());
    store.setValue(QStringLiteral("view/screenshotFolder"), m_lastFolder);
    store.setValue(QStringLiteral("view/compare"), m_sides.isOn());
    store.setValue(QStringLiteral("view/selected"), QLatin1String(kSideNames[m_sides.selected()]));
}

QString PersistenceController::startFolder() const
{
    // The last folder used while it exists; else the pictures folder, made if missing (a
    // fresh account has none); else the home folder.
    if (!m_lastFolder.isEmpty() && QFileInfo(m_lastFolder).isDir())
        return m_lastFolder;
    const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    if (!pictures.isEmpty() && QDir().mkpath(pictures) && QFileInfo(pictures).isDir() && QFileInfo(pictures).isWritable())
        return pictures;
    return QDir::homePath();
}

QString PersistenceController::exportSettings(const QString& path) const
{
    try {
        saveSettingsFile(path, m_sides.selectedSettings());
    } catch (const OutputError& e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

QString PersistenceController::importSettings(const QString& path)
{
    try {
        // Keys the file leaves out keep their current values, as with --settings on the CLI.
        const Settings settings = loadSettingsFile(path, m_sides.selectedSettings());
        m_window.setSettings(m_window.selectedSide(), settings, tr("Import %1").arg(QFileInfo(path).fileName()));
    } catch (const SettingsError& e) {
        // Where the keys are, in the window's words.
        return QString::fromStdString(e.what())
               + (e.isUnknownKey() ? tr("\n\nEvery field of the Properties dock names its key at the top of its tooltip.") : QString());
    }
    emit message(tr("Imported %1").arg(QDir::toNativeSeparators(path)), 8000);
    return QString();
}

void PersistenceController::exportSettingsInteractively()
{
    const QString path = QFileDialog::getSaveFileName(&m_window, tr("Export Settings"),
                                                      QDir(startFolder()).filePath(QStringLiteral("shadowlab-settings.json")),
                                                      tr("ShadowLab settings (*.json)"));
    if (path.isEmpty())
        return;
    const QString error = exportSettings(path);
    if (!error.isEmpty())
        QMessageBox::warning(&m_window, tr("Export Settings"), error);
    else
        emit message(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 8000);
}

void PersistenceController::importSettingsInteractively()
{
    const QString path = QFileDialog::getOpenFileName(&m_window, tr("Import Settings"), startFolder(), tr("ShadowLab settings (*.json)"));
    if (path.isEmpty())
        return;
    const QString error = importSettings(path);
    if (!error.isEmpty())
        QMessageBox::warning(&m_window, tr("Import Settings"), error);
}

} // namespace shadowlab
