#pragma once

#include "CompareController.h"
#include "ImportController.h"
#include "PersistenceController.h"
#include "ScreenshotDialog.h"
#include "Settings.h"
#include "SettingsChange.h"
#include "UndoController.h"
#include "WindowStatusBar.h"

#include <QKeySequence>
#include <QMainWindow>

#include <array>
#include <functional>

class QAction;
class QSplitter;
class QToolBar;
class QUndoStack;

namespace shadowlab {

class AccuracyDock;
class DepthMapView;
class LightAnimation;
class TimelineBar;
class PropertiesDock;
class SceneFileWatcher;
class SceneOpener;
class SceneView;
class TimingController;
class ViewPane;

// The explorer: the lit scene beside the light's depth map, the properties dock, and compare
// mode, where the scene area splits into sides A and B with their own settings and one shared
// camera. The window owns the settings of both sides (always valid ones, in a CompareController);
// views only draw them and the dock only proposes edits. The window lays out the views, docks,
// menus and status bar and wires them; undo, timing, import and persistence are controllers'.
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

    const Settings& settings(Side side) const { return m_sides.settings(std::size_t(side)); }
    // Throws SettingsError when `settings` are not valid; the camera is shared, so setting it
    // on one side sets it on both. The change is one step of that side's undo history, named
    // `undoText` ("Set bias.slope", "Change 5 settings" when empty).
    void setSettings(Side side, const Settings& settings, const QString& undoText = {});

    bool compareMode() const { return m_sides.isOn(); }
    // Compare mode in one view: A left of a divider, B right of it, over the same pixels.
    void setWipe(bool on);
    bool wiping() const;
    void setCompareMode(bool on);
    Side selectedSide() const { return Side(m_sides.selected()); }
    void selectSide(Side side);
    void copyAToB();
    void swapSides();
    void setLightAnimation(bool animate, double degreesPerSecond);

    // Writes a PNG of `target`; returns an empty string or what went wrong. The action's
    // dialog ends here.
    QString saveScreenshot(ScreenshotDialog::Target target, const QString& path);
    // Where Save Screenshot and the settings files start: the last folder used, else the
    // pictures folder (created when missing), else the home folder.
    QString screenshotFolder() { return m_session->startFolder(); }
    // Exports or imports the selected side as JSON with the command line's keys; returns an
    // empty string or what went wrong.
    QString exportSettings(const QString& path) const { return m_session->exportSettings(path); }
    QString importSettings(const QString& path) { return m_session->importSettings(path); }

    // Loads a model or scene file onto the selected side with the light and camera it brings
    // and remembers it among the recent files; returns an empty string or what went wrong, and
    // then the current scene stays.
    QString openScene(const QString& path) { return m_import->open(path); }
    // What File → Open, Open Recent, a drop and the command line do: the file is read in the
    // background with a progress bar and Cancel in the status bar, the current scene stays
    // usable meanwhile, and openScene() applies it once it is ready (a refusal is shown in a
    // message box, "openErrorBox").
    void openSceneInBackground(const QString& path) { m_import->openInBackground(path); }
    SceneOpener* sceneOpener() const { return m_import->opener(); }
    const QStringList& recentScenes() const { return m_import->recentScenes(); }

    SceneView* sceneView(Side side) const { return m_views[std::size_t(side)]; }
    DepthMapView* depthMapView() const { return m_depthView; }
    PropertiesDock* propertiesDock() const { return m_dock; }
    AccuracyDock* accuracyDock() const { return m_accuracyDock; }
    QAction* action(const QString& objectName) const;
    // The status bar's message, whole (on screen it may end in "…"); empty when there is none.
    QString statusMessage() const { return m_status->message(); }
    // Every warning the status bar's warnings button lists now.
    QStringList warnings() const;
    // The undo history of each side: every settings change (dock edits, a sweep point or tuned
    // bias applied, reset, copy and swap, a scene or settings file opened) is a step; the camera
    // is the view's, not a setting one undoes. Edit > Undo works on the selected side's.
    QUndoStack* undoStack(Side side) const { return m_undo->stack(std::size_t(side)); }

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createViews();
    void createDocks();
    void createControllers();
    void createActions();
    void createMeasureActions();
    // After each frame of a side: its time, the fit read-out and the status bar.
    void frameRendered(Side side);
    // The sides' recent frame times to the accuracy dock, beside their error.
    void showFrameTimes();
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createToolBar();
    void createStatusBar();

    void applyEdit(const Settings& settings);
    // Makes the change from `before` (the sides it holds) to the present settings a step of
    // `side`'s undo history.
    void recordChange(const SettingsChange::Sides& before, Side side, const QString& text = {}, bool mayMerge = false);
    // Turns the selected side's light around its target (a Ctrl+drag in a scene view).
    void turnLight(double azimuthDegrees, double elevationDegrees);
    // In the status bar for `timeoutMs` (0: until the next message).
    void showStatusMessage(const QString& text, int timeoutMs) { m_status->setMessage(text, timeoutMs); }
    void showUndoState(const SettingsChange::Sides& target, const SettingsChange::Sides& from);
    void setCamera(const CameraSettings& camera);
    // A checkable action of the View menu calling `toggled` with its state.
    QAction* toggleAction(const QString& text, const QString& name, const QKeySequence& shortcut, const QString& toolTip,
                          const std::function<void(bool)>& toggled);
    // The selected side's scene view's width over its height: what a model's camera is framed for.
    double viewAspect() const;
    // `settings` with the camera of a newly shown scene framed for viewAspect().
    Settings framedForView(Settings settings) const;
    void pushSettings();
    // The sides shown as they now are: the views, and the dock on the selected one.
    void showSides();
    void updateCaptions();
    void updateStatus();
    // The animation's turn of both lights.
    void turnLights(double radians);
    // The scene's clock: both sides share it, and neither playing nor scrubbing is an undo step
    // per frame (a scrub is one when it ends; play and pause are one each).
    void createTimeline();
    void advanceClock(double wallSeconds);
    void scrubTo(double time);
    void showClock();

    void saveScreenshotInteractively();
    void showArtifactsHelp();
    void showAbout();

    // The settings of both sides, compare mode and the selected side; then what acts on them.
    CompareController m_sides;
    UndoController* m_undo = nullptr;
    TimingController* m_timing = nullptr;
    ImportController* m_import = nullptr;
    SceneFileWatcher* m_fileWatcher = nullptr;
    PersistenceController* m_session = nullptr;
    const Persistence m_persistence;

    std::array<SceneView*, 2> m_views{};
    std::array<ViewPane*, 2> m_scenePanes{};
    DepthMapView* m_depthView = nullptr;
    ViewPane* m_depthPane = nullptr;
    QSplitter* m_mainSplitter = nullptr;
    QSplitter* m_sceneSplitter = nullptr;
    PropertiesDock* m_dock = nullptr;
    AccuracyDock* m_accuracyDock = nullptr;

    WindowStatusBar* m_status = nullptr;
    LightAnimation* m_animation = nullptr;
    TimelineBar* m_timeline = nullptr;
    double m_clipLength = 0.0;                  // the shown scene's clip (0: nothing moves)
    SettingsChange::Sides m_scrubStart;         // both sides when a scrub began: its undo step

    QAction* m_compareAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_swapAction = nullptr;
    QAction* m_volumeAction = nullptr;
    QAction* m_animateAction = nullptr;
    QAction* m_screenshotAction = nullptr;
    QAction* m_densityAction = nullptr;
    QAction* m_shadowOnlyAction = nullptr;
    QAction* m_loupeAction = nullptr;
    QAction* m_wipeAction = nullptr;
    QAction* m_freezeAction = nullptr;
    QAction* m_measureAction = nullptr;
    QToolBar* m_toolBar = nullptr;
    QString m_lastFitWarning;   // said once in the status bar, not on every frame
    QString m_sizedScene;       // the scene the dock's slider spans were last fitted to
    QString m_warnedScene;      // the scene whose file the import warnings are of
};

} // namespace shadowlab
