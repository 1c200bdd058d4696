#pragma once

#include <QObject>
#include <QString>
#include <QVariantMap>

#include <vector>

class QAction;
class QDockWidget;
class QSplitter;

namespace shadowlab {

class CompareController;
class ImportController;
class MainWindow;
class SessionAutosave;

// What the explorer keeps between runs, with QSettings: the window's geometry and layout, the
// recent files, the view options, and the session (both sides' settings, compare mode and the
// selected side), saved as it changes through SessionAutosave. After a crash it asks before
// restoring, and does not reopen the file that was being opened then. Disabled, it reads and
// writes nothing (a fresh window on the default scene).
class PersistenceController : public QObject {
    Q_OBJECT

public:
    PersistenceController(MainWindow& window, CompareController& sides, ImportController& import, bool enabled);

    // Restores the layout, then the last session (or asks, after a crash), and from then on
    // saves when the splitter or a dock moves.
    void start(QSplitter* splitter, QAction* lightVolume, const std::vector<QDockWidget*>& docks);
    // Something of the session changed: saved within a second.
    void changed();
    // A scene being read (empty when done).
    void setOpening(const QString& path);
    // `scene` is applied but not drawn yet: a crash before its first frame does not reopen it.
    void setSuspect(const QString& scene, bool flush);
    // A frame of `scene` was drawn.
    void drawn(const QString& scene);
    // A clean end: saved now.
    void end();
    // Where Save Screenshot and the settings files start: the last folder used, else the
    // pictures folder (created when missing), else the home folder.
    QString startFolder() const;
    void setLastFolder(const QString& folder) { m_lastFolder = folder; }

    // Exports or imports the selected side as JSON with the command line's keys; returns an
    // empty string or what went wrong. An import is one undo step.
    QString exportSettings(const QString& path) const;
    QString importSettings(const QString& path);
    void exportSettingsInteractively();
    void importSettingsInteractively();

signals:
    void message(const QString& text, int timeoutMs);
    // The session the user chose to restore is in place: the window shows it.
    void sessionRestored();

private:
    void restoreLayout();
    // The last session's settings, compare mode and side; a side on a model or scene file
    // starts on the default scene and takes its settings once the file is read (in the
    // background). `skipScene` (what was being opened when the last session crashed) is not
    // reopened.
    void restoreSession(const QVariantMap& session, const QString& skipScene = {});
    QVariantMap savedSession() const;   // what restoreSession() reads, as saved
    void offerRestore(const QString& openingAtCrash);
    void save() const;

    MainWindow& m_window;
    CompareController& m_sides;
    ImportController& m_import;
    bool m_enabled;
    SessionAutosave* m_autosave = nullptr;
    QSplitter* m_splitter = nullptr;
    QAction* m_lightVolume = nullptr;
    QString m_lastFolder;
    QString m_openingScene;     // applied, but not yet drawn: cleared after its first frame
    bool m_hold = false;        // while the restore question is open, the crashed session stays on disk
};

} // namespace shadowlab
