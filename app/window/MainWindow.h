#pragma once

#include "FrameTimeHistory.h"
#include "ScreenshotDialog.h"
#include "Settings.h"
#include "SettingsChange.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>
#include <QVariantMap>

#include <array>
#include <optional>

class QAction;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QSplitter;
class QToolBar;
class QUndoGroup;
class QUndoStack;

namespace shadowlab {

class AccuracyDock;
class DepthMapView;
class ElidedLabel;
class PropertiesDock;
class SceneOpener;
class SessionAutosave;
class SceneView;
class ViewPane;

// The explorer: the lit scene beside the light's depth map, the properties dock, and compare
// mode, where the scene area splits into sides A and B with their own settings and one shared
// camera. The window owns the settings of both sides (always valid ones); views only draw them
// and the dock only proposes edits.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    enum class Persistence {
        Restore,    // read and write geometry, layout and last settings with QSettings
        None,       // a fresh window on the default scene (screenshots, scripted use)
    };
    enum class Side { A = 0, B = 1 };

    explicit MainWindow(Persistence persistence = Persistence::Restore, QWidget* parent = nullptr);
    ~MainWindow() override;

    const Settings& settings(Side side) const { return m_settings[std::size_t(side)]; }
    // Throws SettingsError when `settings` are not valid; the camera is shared, so setting it
    // on one side sets it on both. The change is one step of that side's undo history, named
    // `undoText` ("Set bias.slope", "Change 5 settings" when empty).
    void setSettings(Side side, const Settings& settings, const QString& undoText = {});

    bool compareMode() const { return m_compare; }
    void setCompareMode(bool on);
    Side selectedSide() const { return m_selected; }
    void selectSide(Side side);
    void copyAToB();
    void swapSides();
    void setLightAnimation(bool animate, double degreesPerSecond);

    // Writes a PNG of `target`; returns an empty string or what went wrong. The action's
    // dialog ends here.
    QString saveScreenshot(ScreenshotDialog::Target target, const QString& path);
    // Where Save Screenshot and the settings files start: the last folder used, else the
    // pictures folder (created when missing), else the home folder.
    QString screenshotFolder();
    // Exports or imports the selected side as JSON with the command line's keys; returns an
    // empty string or what went wrong.
    QString exportSettings(const QString& path) const;
    QString importSettings(const QString& path);

    // Loads a model or scene file onto the selected side with the light and camera it brings
    // and remembers it among the recent files; returns an empty string or what went wrong, and
    // then the current scene stays.
    QString openScene(const QString& path);
    // What File → Open, Open Recent, a drop and the command line do: the file is read in the
    // background with a progress bar and Cancel in the status bar, the current scene stays
    // usable meanwhile, and openScene() applies it once it is ready (a refusal is shown in a
    // message box, "openErrorBox").
    void openSceneInBackground(const QString& path);
    SceneOpener* sceneOpener() const { return m_opener; }
    const QStringList& recentScenes() const { return m_recentScenes; }

    SceneView* sceneView(Side side) const { return m_views[std::size_t(side)]; }
    DepthMapView* depthMapView() const { return m_depthView; }
    PropertiesDock* propertiesDock() const { return m_dock; }
    AccuracyDock* accuracyDock() const { return m_accuracyDock; }
    QAction* action(const QString& objectName) const;
    // The status bar's message, whole (on screen it may end in "…"); empty when there is none.
    QString statusMessage() const;
    // The undo history of each side: every settings change (dock edits, a sweep point or tuned
    // bias applied, reset, copy and swap, a scene or settings file opened) is a step; the camera
    // is the view's, not a setting one undoes. Edit > Undo works on the selected side's.
    QUndoStack* undoStack(Side side) const { return m_undoStacks[std::size_t(side)]; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMeasureActions();
    void measureFrames(int count);
    void recordFrame(Side side);
    // The sides' recent frame times to the accuracy dock, beside their error.
    void showFrameTimes();
    QString timingText(Side side) const;
    QString compareTimingText() const;
    QString timingToolTip() const;
    void createMenus();
    void createToolBar();
    void createStatusBar();
    void restoreLayout();
    // The last session's settings, compare mode and side; a side on a model or scene file
    // starts on the default scene and takes its settings once the file is read (in the
    // background). `skipScene` (what was being opened when the last session crashed) is not
    // reopened.
    void restoreSession(const QVariantMap& session, const QString& skipScene = {});
    QVariantMap savedSession() const;   // what restoreSession() reads, as saved
    void offerRestore(const QString& openingAtCrash);
    void saveState() const;
    void sessionChanged();
    void sceneOpenFinished(const QString& path, const QString& error, bool cancelled);
    void showOpenError(const QString& error);

    void applyEdit(const Settings& settings);
    // Makes the change from `before` (the sides it holds) to the present settings a step of
    // `side`'s undo history.
    void recordChange(const SettingsChange::Sides& before, Side side, QString text = {}, bool mayMerge = false);
    // Turns the selected side's light around its target (a Ctrl+drag in a scene view).
    void turnLight(double azimuthDegrees, double elevationDegrees);
    // In the status bar for `timeoutMs` (0: until the next message).
    void showStatusMessage(const QString& text, int timeoutMs);
    // Sets one side (the other follows onto its scene), returning what both were for the undo step.
    SettingsChange::Sides setSide(Side side, const Settings& settings);
    void showUndoState(const SettingsChange::Sides& target, const SettingsChange::Sides& from);
    void setCamera(const CameraSettings& camera);
    void pushSettings();
    void updateCaptions();
    void updateStatus();
    void animateLight();

    void openSceneInteractively();
    void openSceneReporting(const QString& path);
    void updateRecentMenu();
    void saveScreenshotInteractively();
    void exportSettingsInteractively();
    void importSettingsInteractively();
    void showArtifactsHelp();
    void showAbout();

    Persistence m_persistence;
    SessionAutosave* m_autosave = nullptr;
    SceneOpener* m_opener = nullptr;
    QWidget* m_openBox = nullptr;           // status bar: "Opening engine.ply" [progress] [Cancel]
    QLabel* m_openLabel = nullptr;
    QProgressBar* m_openProgress = nullptr;
    QPushButton* m_openCancel = nullptr;
    // Sides of the restored session waiting for their scene file, and the files still to read.
    std::array<std::optional<Settings>, 2> m_pendingRestore;
    QStringList m_restoreQueue;
    QString m_openingScene;     // applied, but not yet drawn: cleared after its first frame
    bool m_holdAutosave = false;    // while the restore question is open, the crashed session stays on disk
    QStringList m_recentScenes;     // newest first
    QMenu* m_recentMenu = nullptr;
    std::array<Settings, 2> m_settings;
    Side m_selected = Side::A;
    bool m_compare = false;

    std::array<SceneView*, 2> m_views{};
    std::array<ViewPane*, 2> m_scenePanes{};
    DepthMapView* m_depthView = nullptr;
    ViewPane* m_depthPane = nullptr;
    QSplitter* m_mainSplitter = nullptr;
    QSplitter* m_sceneSplitter = nullptr;
    PropertiesDock* m_dock = nullptr;
    AccuracyDock* m_accuracyDock = nullptr;

    QLabel* m_texelLabel = nullptr;
    QLabel* m_timingLabel = nullptr;
    QLabel* m_mapLabel = nullptr;

    QTimer m_animationTimer;
    ElidedLabel* m_messageLabel = nullptr;
    QTimer m_messageTimer;              // clears a message after its time
    QElapsedTimer m_animationClock;
    double m_animationSpeed = 30.0;     // degrees per second

    QAction* m_compareAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_swapAction = nullptr;
    QAction* m_volumeAction = nullptr;
    QAction* m_animateAction = nullptr;
    QAction* m_screenshotAction = nullptr;
    QToolBar* m_toolBar = nullptr;
    QString m_screenshotFolder;
    QString m_lastFitWarning;   // said once in the status bar, not on every frame
    QUndoGroup* m_undoGroup = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    std::array<QUndoStack*, 2> m_undoStacks{};
    quint64 m_gesture = 0;      // mouse and key presses so far: edits between two presses merge

    static constexpr int kMeasuredFrames = 100;
    std::array<FrameTimeHistory, 2> m_history;  // rolling wall times per side, for the status bar
    std::array<std::optional<Settings>, 2> m_historyState;
    QString m_sizedScene;
    double m_lightAzimuth = 0.0;    // kept while a drag passes over the light's pole       // the scene the dock's slider spans were last fitted to  // what those frames rendered (no camera)
    int m_measureLeft = 0;      // frames still to draw for Measure 100 Frames
    QAction* m_densityAction = nullptr;
    QAction* m_measureAction = nullptr;
};

} // namespace shadowlab
