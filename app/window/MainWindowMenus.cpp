#include "MainWindow.h"

#include "AccuracyDock.h"
#include "DepthMapView.h"
#include "LightAnimation.h"
#include "Loupe.h"
#include "PropertiesDock.h"
#include "Renderer.h"
#include "SceneLibrary.h"
#include "SceneView.h"
#include "TimingController.h"
#include "ViewPane.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenuBar>
#include <QToolBar>

// The main window's actions, menus, tool bar and status bar (the rest is in MainWindow.cpp).
namespace shadowlab {

void MainWindow::createActions()
{
    m_compareAction = new QAction(tr("&Compare A | B"), this);
    m_compareAction->setObjectName(QStringLiteral("compareAction"));
    m_compareAction->setCheckable(true);
    m_compareAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_compareAction->setToolTip(tr("Split the scene into sides A and B with their own settings and one camera (Ctrl+D)"));
    connect(m_compareAction, &QAction::toggled, this, &MainWindow::setCompareMode);
    m_wipeAction = new QAction(tr("&Wipe A | B"), this);
    m_wipeAction->setObjectName(QStringLiteral("wipeAction"));
    m_wipeAction->setCheckable(true);
    m_wipeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
    m_wipeAction->setToolTip(tr("Compare mode over the same pixels: side A left of a divider and side B right of it, in one view; drag "
                                "the divider across (Ctrl+Shift+D)"));
    connect(m_wipeAction, &QAction::toggled, this, &MainWindow::setWipe);

    m_copyAction = new QAction(tr("Copy A → B"), this);
    m_copyAction->setObjectName(QStringLiteral("copyAction"));
    m_copyAction->setToolTip(tr("Give side B the settings of side A"));
    connect(m_copyAction, &QAction::triggered, this, &MainWindow::copyAToB);

    m_swapAction = new QAction(tr("Swap A ↔ B"), this);
    m_swapAction->setObjectName(QStringLiteral("swapAction"));
    m_swapAction->setToolTip(tr("Exchange the settings of the two sides"));
    connect(m_swapAction, &QAction::triggered, this, &MainWindow::swapSides);

    m_volumeAction = new QAction(tr("Light &Volume"), this);
    m_volumeAction->setObjectName(QStringLiteral("lightVolumeAction"));
    m_volumeAction->setCheckable(true);
    m_volumeAction->setChecked(true);
    m_volumeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_volumeAction->setToolTip(tr("Draw the light's volume (what the shadow map covers) as a wireframe (Ctrl+L)"));
    connect(m_volumeAction, &QAction::toggled, this, [this](bool on) {
        for (SceneView* view : m_views)
            view->setShowLightVolume(on);
    });

    m_animateAction = new QAction(tr("&Animate Light"), this);
    m_animateAction->setObjectName(QStringLiteral("animateAction"));
    m_animateAction->setCheckable(true);
    m_animateAction->setToolTip(tr("Circle the light around its target (speed in the Light group)"));
    connect(m_animateAction, &QAction::toggled, this, [this](bool on) { setLightAnimation(on, m_animation->speed()); });

    m_screenshotAction = new QAction(tr("Save &Screenshot…"), this);
    m_screenshotAction->setObjectName(QStringLiteral("screenshotAction"));
    m_screenshotAction->setShortcut(QKeySequence::Save);
    m_screenshotAction->setToolTip(tr("Save the scene view, the depth-map view or the whole window as PNG (Ctrl+S)"));
    connect(m_screenshotAction, &QAction::triggered, this, &MainWindow::saveScreenshotInteractively);

    m_copyAction->setEnabled(false);
    m_swapAction->setEnabled(false);
}

void MainWindow::createMenus()
{
    createFileMenu();
    createEditMenu();
    createViewMenu();
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* artifacts = help->addAction(tr("Shadow &Artifacts"), this, &MainWindow::showArtifactsHelp);
    artifacts->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About ShadowLab"), this, &MainWindow::showAbout);
}

void MainWindow::createFileMenu()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Scene…"), m_import, &ImportController::openInteractively);
    open->setObjectName(QStringLiteral("openSceneAction"));
    open->setShortcut(QKeySequence::Open);
    open->setToolTip(tr("Load a model (glTF, OBJ, PLY, STL, COLLADA, FBX) or a scene file (.json); dropping a file on the view does the same (Ctrl+O)"));
    QMenu* recent = file->addMenu(tr("Open &Recent"));
    recent->setObjectName(QStringLiteral("recentScenesMenu"));
    m_import->setRecentMenu(recent);
    QAction* limits = file->addAction(tr("Import &Limits…"), m_import, &ImportController::editLimits);
    limits->setObjectName(QStringLiteral("importLimitsAction"));
    limits->setToolTip(tr("How long and how much memory reading one model file may take"));
    file->addSeparator();
    file->addAction(m_screenshotAction);
    file->addSeparator();
    file->addAction(tr("&Export Settings…"), m_session, &PersistenceController::exportSettingsInteractively)->setObjectName(QStringLiteral("exportAction"));
    file->addAction(tr("&Import Settings…"), m_session, &PersistenceController::importSettingsInteractively)->setObjectName(QStringLiteral("importAction"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

void MainWindow::createEditMenu()
{
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undo->createUndoAction(this));
    edit->addAction(m_undo->createRedoAction(this));
    edit->addSeparator();
    edit->addAction(m_copyAction);
    edit->addAction(m_swapAction);
}

void MainWindow::createViewMenu()
{
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_compareAction);
    view->addAction(m_wipeAction);
    view->addSeparator();
    view->addAction(m_volumeAction);
    view->addAction(m_animateAction);
    QAction* resetCamera = view->addAction(tr("&Reset Camera"), this, [this] {
        try {
            setCamera(presetCamera(m_sides.settings(0).scene, viewAspect()));
        } catch (const SettingsError& e) {
            showStatusMessage(tr("Cannot reset the camera: %1").arg(QString::fromUtf8(e.what())), 8000);
        }
    });
    resetCamera->setToolTip(tr("Back to the scene's own camera, a model framed whole in the view (R in a scene view)"));
    QAction* fitMap = view->addAction(tr("&Fit Depth Map"), m_depthView, &DepthMapView::resetZoom);
    fitMap->setObjectName(QStringLiteral("fitDepthMapAction"));
    fitMap->setToolTip(tr("The whole shadow map in its pane (Home or double-click in the pane)"));
    QAction* frameFootprint = view->addAction(tr("Frame Camera &Footprint"), m_depthView, &DepthMapView::frameFootprint);
    frameFootprint->setObjectName(QStringLiteral("frameFootprintAction"));
    frameFootprint->setToolTip(tr("The shadow map with all the camera sees of the scene around it (F in the pane)"));
    fitMap->setIcon(DepthMapView::framingIcon(false));
    frameFootprint->setIcon(DepthMapView::framingIcon(true));
    m_depthPane->addCaptionButton(fitMap);
    m_depthPane->addCaptionButton(frameFootprint);
    QAction* redrawCache = view->addAction(tr("Redraw &Cached Shadows"), this, [this] {
        for (SceneView* sceneView : m_views) {
            if (sceneView)
                sceneView->redrawCachedShadows();
        }
    });
    redrawCache->setObjectName(QStringLiteral("redrawCachedShadowsAction"));
    redrawCache->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    redrawCache->setToolTip(tr("With shadow.cache=on-demand, draw the moving casters where the shadow map is stale, once (Ctrl+Shift+R)"));
    view->addAction(m_densityAction);
    view->addAction(m_shadowOnlyAction);
    view->addAction(m_loupeAction);
    view->addAction(m_freezeAction);
    view->addAction(m_measureAction);
    view->addSeparator();
    view->addAction(m_dock->toggleViewAction());
    view->addAction(m_accuracyDock->toggleViewAction());
    view->addAction(m_toolBar->toggleViewAction());
}

QAction* MainWindow::toggleAction(const QString& text, const QString& name, const QKeySequence& shortcut, const QString& toolTip,
                                  const std::function<void(bool)>& toggled)
{
    auto* action = new QAction(text, this);
    action->setObjectName(name);
    action->setCheckable(true);
    action->setShortcut(shortcut);
    action->setToolTip(toolTip);
    connect(action, &QAction::toggled, this, toggled);
    return action;
}

void MainWindow::createMeasureActions()
{
    // The views' own settings (both sides): what is shown, never what is measured.
    const auto forBothSides = [this](void (*set)(Settings&, bool)) {
        return [this, set](bool on) {
            for (Settings& s : m_sides.sides())
                set(s, on);
            showSides();
        };
    };
    m_densityAction = toggleAction(tr("&Texel Density Overlay"), QStringLiteral("texelDensityAction"), {},
                                   tr("Tint the scene by screen pixels per shadow texel: blue under 1, green 1–2, yellow 4, red 8 and up "
                                      "(blocky); the setting shading.texel_density"),
                                   forBothSides([](Settings& s, bool on) { s.shading.texelDensity = on; }));
    m_shadowOnlyAction = toggleAction(tr("&Shadow Only"), QStringLiteral("shadowOnlyAction"), QKeySequence(Qt::CTRL | Qt::Key_J),
                                      tr("The shadow term alone: white lit, black shadowed, grey partial (a filter's moiré shows here), dark "
                                         "blue facing away from the light; no textures or lighting (Ctrl+J; the setting shading.shadow_only)"),
                                      forBothSides([](Settings& s, bool on) { s.shading.shadowOnly = on; }));
    m_loupeAction = toggleAction(tr("&Loupe"), QStringLiteral("loupeAction"), QKeySequence(Qt::CTRL | Qt::Key_M),
                                 tr("Magnify the pixels under the pointer %1 times beside it, with the colour of the one in the middle: "
                                    "acne, moiré and a filter's steps at their own size (Ctrl+M)").arg(Loupe::kZoom),
                                 [this](bool on) {
                                     for (SceneView* view : m_views)
                                         view->setLoupe(on);
                                 });
    m_freezeAction = toggleAction(tr("&Freeze Shadow Frustum"), QStringLiteral("freezeAction"), QKeySequence(Qt::CTRL | Qt::Key_F),
                                  tr("Keep the light fitted to the camera as it is now (its culling, cascades and fitted volume) while you "
                                     "move the camera away to look at them from outside; the frozen camera is drawn (Ctrl+F)"),
                                  [this](bool on) {
                                      for (SceneView* view : m_views)
                                          view->setFrozenCamera(on ? std::optional(m_sides.selectedSettings().camera) : std::nullopt);
                                  });
    m_measureAction = m_timing->createMeasureAction(this);
}

void MainWindow::showFrameTimes()
{
    m_accuracyDock->setFrameTimes(m_timing->summaries(), m_timing->cpuTime());
}

void MainWindow::createToolBar()
{
    QToolBar* bar = m_toolBar = addToolBar(tr("Toolbar"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setMovable(false);
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(m_compareAction);
    bar->addAction(m_copyAction);
    bar->addAction(m_swapAction);
    bar->addSeparator();
    bar->addAction(m_volumeAction);
    bar->addAction(m_animateAction);
    bar->addSeparator();
    bar->addAction(m_screenshotAction);
}

void MainWindow::createStatusBar()
{
    m_status = new WindowStatusBar(m_import->createProgressBox());
    m_status->setTiming({}, m_timing->toolTip());
    setStatusBar(m_status);
    connect(m_import, &ImportController::warningsFound, this, [this](const QStringList& warnings) {
        m_warnedScene = m_sides.selectedSettings().scene;
        m_status->setWarnings(QStringLiteral("import"), warnings);
    });
}

QAction* MainWindow::action(const QString& objectName) const
{
    return findChild<QAction*>(objectName);
}

} // namespace shadowlab
