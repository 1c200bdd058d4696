#pragma once

#include "SceneFileError.h"
#include "Settings.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <functional>
#include <optional>

class QDragEnterEvent;
class QDropEvent;
class QLabel;
class QMenu;
class QProgressBar;
class QWidget;

namespace shadowlab {

class CompareController;
class SceneOpener;

// Opening models and scene files: read in the background by a SceneOpener with a progress bar
// and Cancel in the status bar, then applied to the selected side; the recent files and their
// menu; a refusal in a message box ("openErrorBox") while the current scene stays. Also reads
// the scene files of a restored session, whose sides take their saved settings once read.
class ImportController : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaxRecentScenes = 8;
    // Makes `settings` the selected side's, one undo step named `undoText`; throws
    // SettingsError when they are not valid.
    using Apply = std::function<void(const Settings& settings, const QString& undoText)>;

    // `window` parents the dialogs and message boxes.
    ImportController(QWidget* window, CompareController& sides, Apply apply);

    SceneOpener* opener() const { return m_opener; }
    // Loads a model or scene file onto the selected side at once (MainWindow::openScene()).
    QString open(const QString& path);
    void openInBackground(const QString& path);
    // Reads a shown file again in the background after it changed on disk (SceneFileWatcher):
    // the views draw its new contents with their settings as they are; a file that cannot be read
    // now leaves the last good contents, and the status bar says why.
    void reload(const QString& path);
    void openInteractively();
    void cancel();
    // File > Import Limits…: how long and how much memory the importer may take on one file,
    // for the rest of this run (the command line's --import-time-limit and --import-memory-limit).
    void editLimits();
    // One local file dragged over the window or dropped on it (a model or a scene file).
    void dragEnter(QDragEnterEvent* event);
    void drop(QDropEvent* event);

    const QStringList& recentScenes() const { return m_recentScenes; }
    void setRecentScenes(const QStringList& paths);
    // File > Open Recent, kept up to date from now on.
    void setRecentMenu(QMenu* menu);
    // The status bar's "Opening engine.ply" [progress] [Cancel], shown while a file is read.
    QWidget* createProgressBox();

    // A file the user opens now wins over the session's files.
    bool userOpening() const;
    // `side` of a restored session waits for its scene file, read once startRestore() runs.
    void queueRestore(std::size_t side, const Settings& settings);
    void startRestore();
    // What a side waits for; saved in its place, so a crash meanwhile loses nothing.
    const std::optional<Settings>& pendingRestore(std::size_t side) const { return m_pendingRestore[side]; }

signals:
    void readingStarted(const QString& absolutePath);
    void readingEnded();
    // `scene` is shown, but not yet drawn: `flush` to say so on disk at once.
    void sceneApplied(const QString& scene, bool flush);
    // The user opened a model or scene file, now shown (not a restored session's).
    void fileOpened(const QString& path);
    // What the file just opened warns of, each warning whole (empty: none); in place of the last file's.
    void warningsFound(const QStringList& warnings);
    // Sides of the restored session took their saved settings (or stayed, on a refusal).
    void restoredSidesChanged();
    // A shown file was read again (reload()): the views draw it anew.
    void sceneReloaded(const QString& path);
    void message(const QString& text, int timeoutMs);

private:
    void finished(const QString& path, const QString& error, bool cancelled);
    void finishRestore(const QString& path, const QString& error, bool cancelled);
    void startReload();
    void finishReload(const QString& path, const QString& error, bool cancelled);
    // `limit`: the import limit that stopped `path`, which the box offers to raise and try again.
    void showOpenError(const QString& path, const QString& error, SceneFileError::Limit limit = SceneFileError::Limit::None);
    void updateRecentMenu();

    QWidget* m_window;
    CompareController& m_sides;
    Apply m_apply;
    SceneOpener* m_opener = nullptr;
    QWidget* m_openBox = nullptr;
    QLabel* m_openLabel = nullptr;
    QProgressBar* m_openProgress = nullptr;
    // Sides of the restored session waiting for their scene file, and the files still to read.
    std::array<std::optional<Settings>, 2> m_pendingRestore;
    QStringList m_restoreQueue;
    QStringList m_reloadQueue;      // files to read again after they changed on disk
    QString m_reloading;            // the one being read again now
    QStringList m_recentScenes;     // newest first
    QMenu* m_recentMenu = nullptr;
};

} // namespace shadowlab
