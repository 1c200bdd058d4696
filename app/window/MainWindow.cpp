#include "MainWindow.h"

#include "AccuracyDock.h"
#include "AccuracyMetricsPanel.h"
#include "ArtifactsHelp.h"
#include "DepthMapView.h"
#include "ElidedLabel.h"
#include "FrameStatsText.h"
#include "FrameTimeHistory.h"
#include "ImageFile.h"
#include "LightMath.h"
#include "MomentMath.h"
#include "OutputFile.h"
#include "PropertiesDock.h"
#include "Renderer.h"
#include "ModelImporter.h"
#include "SceneLibrary.h"
#include "SceneLoader.h"
#include "SceneOpener.h"
#include "SessionAutosave.h"
#include "SceneView.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "SettingsSummary.h"
#include "ViewPane.h"
#include "WheelGuard.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPainter>
#include <QPixmap>
#include <QPolygonF>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoGroup>
#include <QUndoStack>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr int kAnimationIntervalMs = 33;
constexpr int kMaxRecentScenes = 8;
const char* const kSideNames[] = {"A", "B"};

// The depth pane's framing buttons: the map's square filling the frame, or the small square
// inside the camera's orange footprint.
QIcon framingIcon(bool withFootprint)
{
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor light(225, 228, 235);
    painter.setPen(QPen(light, 2.5));
    if (withFootprint) {
        painter.drawRect(QRectF(11, 11, 10, 10));
        painter.setPen(QPen(QColor(255, 150, 40), 2.5));
        painter.drawPolygon(QPolygonF{QPointF(4, 28), QPointF(28, 28), QPointF(22, 4), QPointF(10, 4)});
    } else {
        painter.drawRect(QRectF(7, 7, 18, 18));
        for (const QPointF corner : {QPointF(2, 2), QPointF(30, 2), QPointF(30, 30), QPointF(2, 30)}) {
            const QPointF in((corner.x() < 16 ? 1 : -1) * 6.0, (corner.y() < 16 ? 1 : -1) * 6.0);
            painter.drawLine(corner, corner + QPointF(in.x(), 0));
            painter.drawLine(corner, corner + QPointF(0, in.y()));
        }
    }
    return QIcon(pixmap);
}

std::size_t index(MainWindow::Side side)
{
    return std::size_t(side);
}

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

MainWindow::MainWindow(Persistence persistence, QWidget* parent) : QMainWindow(parent), m_persistence(persistence)
{
    setWindowTitle(tr("ShadowLab"));
    setAcceptDrops(true);   // a model or scene file dropped anywhere on the window, the views included
    m_autosave = new SessionAutosave([this] { saveState(); }, this);
    m_opener = new SceneOpener(this);
    connect(m_opener, &SceneOpener::finished, this, &MainWindow::sceneOpenFinished);
    m_settings[0] = presetSettings(QStringLiteral("seed"));
    m_settings[1] = m_settings[0];

    for (std::size_t i = 0; i < 2; ++i) {
        m_views[i] = new SceneView;
        m_views[i]->setObjectName(QStringLiteral("sceneView%1").arg(QLatin1String(kSideNames[i])));
        m_scenePanes[i] = new ViewPane(m_views[i]);
        const Side side = Side(i);
        connect(m_views[i], &SceneView::cameraEdited, this, &MainWindow::setCamera);
        connect(m_views[i], &SceneView::lightTurned, this, [this, side](double azimuth, double elevation) {
            selectSide(side);
            turnLight(azimuth, elevation);
        });
        connect(m_views[i], &SceneView::activated, this, [this, side] { selectSide(side); });
        connect(m_views[i], &SceneView::frameRendered, this, [this, side] {
            recordFrame(side);
            if (!m_openingScene.isEmpty() && m_settings[index(side)].scene == m_openingScene) {
                m_openingScene.clear();     // drawn: no longer a suspect after a crash
                m_autosave->setOpening({});
            }
            // Both sides are measured over side A's pixels (one reference serves both).
            if (side == Side::A)
                m_accuracyDock->setViewSize(m_views[0]->size() * m_views[0]->devicePixelRatio());
            if (side != m_selected)
                return;
            updateStatus();
            if (const Renderer* renderer = m_views[index(side)]->renderer(); renderer && m_views[index(side)]->renderedSettings()) {
                // The dock's sliders follow the size of the scene now drawn.
                if (const Scene* scene = renderer->scene(); scene && scene->name != m_sizedScene) {
                    m_sizedScene = scene->name;
                    const Bounds models = scene->modelBounds();
                    m_dock->setSceneSize(models.center(), glm::length(models.max - models.min) * 0.5);
                }
                const FittedLight& fit = renderer->lastFit();
                m_dock->showFit(fit, m_views[index(side)]->renderedSettings()->light);
                const std::vector<SettingsIssue> warnings = fitWarnings(fit);
                if (!warnings.empty() && warnings.front().message != m_lastFitWarning)
                    showStatusMessage(tr("Warning: %1").arg(warnings.front().message), 10000);
                m_lastFitWarning = warnings.empty() ? QString() : warnings.front().message;
            }
        });
        connect(m_views[i], &SceneView::renderFailed, this, [this, side](const QString& key, const QString& message) {
            if (side == m_selected)
                m_dock->showError(key, message);
            showStatusMessage(tr("%1: %2 — showing the last settings that worked").arg(QLatin1String(kSideNames[index(side)]), message), 8000);
        });
    }
    m_depthView = new DepthMapView;
    m_depthView->setObjectName(QStringLiteral("depthMapView"));
    m_depthPane = new ViewPane(m_depthView);

    m_sceneSplitter = new QSplitter(Qt::Horizontal);
    m_sceneSplitter->setChildrenCollapsible(false);
    m_sceneSplitter->addWidget(m_scenePanes[0]);
    m_sceneSplitter->addWidget(m_scenePanes[1]);
    m_mainSplitter = new QSplitter(Qt::Horizontal);
    m_mainSplitter->setObjectName(QStringLiteral("mainSplitter"));
    m_mainSplitter->setChildrenCollapsible(false); // a collapsed view never draws
    m_mainSplitter->addWidget(m_sceneSplitter);
    m_mainSplitter->addWidget(m_depthPane);
    m_mainSplitter->setStretchFactor(0, 3);
    m_mainSplitter->setStretchFactor(1, 2);
    m_scenePanes[1]->setVisible(false);
    setCentralWidget(m_mainSplitter);

    // One undo history per side; the selected side's is the one Edit > Undo works on.
    m_undoGroup = new QUndoGroup(this);
    for (std::size_t i = 0; i < 2; ++i) {
        m_undoStacks[i] = new QUndoStack(m_undoGroup);
        m_undoStacks[i]->setObjectName(QStringLiteral("undoStack%1").arg(QLatin1String(kSideNames[i])));
    }
    m_undoGroup->setActiveStack(m_undoStacks[0]);
    qApp->installEventFilter(this);    // counts presses, so one drag is one undo step

    m_dock = new PropertiesDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_dock);
    connect(m_dock, &PropertiesDock::settingsEdited, this, &MainWindow::applyEdit);
    connect(m_dock, &PropertiesDock::warningsChanged, this, [this](const QString& text) {
        if (!text.isEmpty())
            showStatusMessage(tr("Warning: %1").arg(text), 10000);
    });
    connect(m_dock, &PropertiesDock::animationChanged, this, &MainWindow::setLightAnimation);

    // Accuracy: measures the scene (both sides in compare mode) against the ray-traced
    // reference; each side's error image lies over its view, and a point of the sweep chart
    // becomes the selected side's settings.
    m_accuracyDock = new AccuracyDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_accuracyDock);
    tabifyDockWidget(m_dock, m_accuracyDock);
    m_dock->raise();
    connect(m_accuracyDock, &AccuracyDock::errorOverlayChanged, this,
            [this](int side, const QImage& image) { m_views[std::size_t(side)]->setErrorOverlay(image); });
    connect(m_accuracyDock, &AccuracyDock::applySettingsRequested, this, [this](const Settings& settings) {
        try {
            setSettings(m_selected, settings, tr("Apply measured configuration"));
        } catch (const SettingsError& e) {
            showStatusMessage(tr("Cannot apply that configuration: %1").arg(QString::fromUtf8(e.what())), 8000);
        }
    });
    connect(m_depthView, &DepthMapView::texelHovered, this,
            [this](const QString& text) { m_texelLabel->setText(text.isEmpty() ? text : tr("under pointer: %1").arg(text)); });

    m_animationTimer.setInterval(kAnimationIntervalMs);
    connect(&m_animationTimer, &QTimer::timeout, this, &MainWindow::animateLight);

    // Over the docks the wheel scrolls; a field takes it once clicked.
    WheelGuard::guardFields(m_dock);
    WheelGuard::guardFields(m_accuracyDock);

    createActions();
    createMeasureActions();
    createToolBar();
    createMenus();
    createStatusBar();
    resize(1200, 750);
    // The dock as narrow as its fields read well: the views are what the window is for.
    resizeDocks({m_dock}, {400}, Qt::Horizontal);
    m_mainSplitter->setSizes({480, 320});

    if (m_persistence == Persistence::Restore) {
        const bool crashed = m_autosave->begin();
        restoreLayout();
        if (crashed) {
            m_holdAutosave = true;
            QTimer::singleShot(0, this, [this, opening = m_autosave->openingAtStart()] { offerRestore(opening); });
        } else {
            restoreSession(savedSession());
        }
        // The layout is part of the session too.
        connect(m_mainSplitter, &QSplitter::splitterMoved, this, &MainWindow::sessionChanged);
        for (QDockWidget* dock : {static_cast<QDockWidget*>(m_dock), static_cast<QDockWidget*>(m_accuracyDock)}) {
            connect(dock, &QDockWidget::dockLocationChanged, this, &MainWindow::sessionChanged);
            connect(dock, &QDockWidget::topLevelChanged, this, &MainWindow::sessionChanged);
            connect(dock, &QDockWidget::visibilityChanged, this, &MainWindow::sessionChanged);
        }
    }
    pushSettings();
    selectSide(m_selected);
}

MainWindow::~MainWindow() = default;

void MainWindow::sessionChanged()
{
    if (m_persistence == Persistence::Restore && !m_holdAutosave)
        m_autosave->changed();
}

void MainWindow::createActions()
{
    m_compareAction = new QAction(tr("&Compare A | B"), this);
    m_compareAction->setObjectName(QStringLiteral("compareAction"));
    m_compareAction->setCheckable(true);
    m_compareAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_compareAction->setToolTip(tr("Split the scene into sides A and B with their own settings and one camera (Ctrl+D)"));
    connect(m_compareAction, &QAction::toggled, this, &MainWindow::setCompareMode);

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
    connect(m_animateAction, &QAction::toggled, this, [this](bool on) { setLightAnimation(on, m_animationSpeed); });

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
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open Scene…"), this, &MainWindow::openSceneInteractively);
    open->setObjectName(QStringLiteral("openSceneAction"));
    open->setShortcut(QKeySequence::Open);
    open->setToolTip(tr("Load a model (glTF, OBJ, PLY, STL, COLLADA, FBX) or a scene file (.json); dropping a file on the view does the same (Ctrl+O)"));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentScenesMenu"));
    updateRecentMenu();
    file->addSeparator();
    file->addAction(m_screenshotAction);
    file->addSeparator();
    file->addAction(tr("&Export Settings…"), this, &MainWindow::exportSettingsInteractively)->setObjectName(QStringLiteral("exportAction"));
    file->addAction(tr("&Import Settings…"), this, &MainWindow::importSettingsInteractively)->setObjectName(QStringLiteral("importAction"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_undoAction = m_undoGroup->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setToolTip(tr("Take back the last settings change of this side (Ctrl+Z)"));
    edit->addAction(undo);
    QAction* redo = m_redoAction = m_undoGroup->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redo->setToolTip(tr("Make the change taken back again (Ctrl+Shift+Z)"));
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(m_copyAction);
    edit->addAction(m_swapAction);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_compareAction);
    view->addSeparator();
    view->addAction(m_volumeAction);
    view->addAction(m_animateAction);
    QAction* resetCamera = view->addAction(tr("&Reset Camera"), this, [this] {
        try {
            setCamera(presetSettings(m_settings[0].scene).camera);
        } catch (const SettingsError& e) {
            showStatusMessage(tr("Cannot reset the camera: %1").arg(QString::fromUtf8(e.what())), 8000);
        }
    });
    resetCamera->setToolTip(tr("Back to the scene preset's camera (R in a scene view)"));
    QAction* fitMap = view->addAction(tr("&Fit Depth Map"), m_depthView, &DepthMapView::resetZoom);
    fitMap->setObjectName(QStringLiteral("fitDepthMapAction"));
    fitMap->setToolTip(tr("The whole shadow map in its pane (Home or double-click in the pane)"));
    QAction* frameFootprint = view->addAction(tr("Frame Camera &Footprint"), m_depthView, &DepthMapView::frameFootprint);
    frameFootprint->setObjectName(QStringLiteral("frameFootprintAction"));
    frameFootprint->setToolTip(tr("The shadow map with all the camera sees of the scene around it (F in the pane)"));
    fitMap->setIcon(framingIcon(false));
    frameFootprint->setIcon(framingIcon(true));
    m_depthPane->addCaptionButton(fitMap);
    m_depthPane->addCaptionButton(frameFootprint);
    view->addAction(m_densityAction);
    view->addAction(m_measureAction);
    view->addSeparator();
    view->addAction(m_dock->toggleViewAction());
    view->addAction(m_accuracyDock->toggleViewAction());
    view->addAction(m_toolBar->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* artifacts = help->addAction(tr("Shadow &Artifacts"), this, &MainWindow::showArtifactsHelp);
    artifacts->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About ShadowLab"), this, &MainWindow::showAbout);
}

void MainWindow::createMeasureActions()
{
    m_densityAction = new QAction(tr("&Texel Density Overlay"), this);
    m_densityAction->setObjectName(QStringLiteral("texelDensityAction"));
    m_densityAction->setCheckable(true);
    m_densityAction->setToolTip(tr("Tint the scene by screen pixels per shadow texel: blue under 1, green 1–2, yellow 4, red 8 and up (blocky); "
                                   "the setting shading.texel_density"));
    connect(m_densityAction, &QAction::toggled, this, [this](bool on) {
        for (Settings& s : m_settings)
            s.shading.texelDensity = on;
        pushSettings();
        m_dock->setSettings(m_settings[index(m_selected)]);
    });
    m_measureAction = new QAction(tr("&Measure 100 Frames"), this);
    m_measureAction->setObjectName(QStringLiteral("measureAction"));
    m_measureAction->setToolTip(tr("Render the selected side 100 times, the shadow pass included, and show the medians and spread"));
    connect(m_measureAction, &QAction::triggered, this, [this] { measureFrames(kMeasuredFrames); });
}

void MainWindow::measureFrames(int count)
{
    for (std::size_t i = 0; i < 2; ++i) {
        if (i == index(m_selected) || m_compare) {
            m_history[i].clear();
            m_history[i].setCapacity(count);
        }
    }
    m_measureLeft = count;
    m_measureAction->setEnabled(false);
    showStatusMessage(tr("Measuring %1 frames…").arg(count), 0);
    m_views[index(m_selected)]->redrawForMeasurement();
    if (m_compare)
        m_views[1 - index(m_selected)]->redrawForMeasurement();
}

void MainWindow::recordFrame(Side side)
{
    const Renderer* renderer = m_views[index(side)]->renderer();
    if (!renderer || !m_views[index(side)]->renderedSettings())
        return;
    // One window of frame times per settings state: a frame of other settings says nothing
    // about these. The camera is the view's, and an animated light moves every frame.
    Settings state = *m_views[index(side)]->renderedSettings();
    state.camera = {};
    if (m_animationTimer.isActive())
        state.light.position = {};
    if (m_historyState[index(side)] != state) {
        m_history[index(side)].clear();
        m_historyState[index(side)] = state;
    }
    m_history[index(side)].add(renderer->lastFrame());
    showFrameTimes();
    if (m_measureLeft > 0) {
        // Each side redraws itself (shadow pass included) until the selected one has its frames.
        if (side == m_selected && --m_measureLeft == 0) {
            m_measureAction->setEnabled(true);
            // Short in the status bar; every pass with its spread stays in the accuracy dock's cost table.
            const FrameTimeHistory::Summary s = m_history[index(side)].summary();
            showStatusMessage(tr("%1 frames: %2 ms a frame (p10–p90 %3–%4) — see Accuracy → Cost")
                                  .arg(s.frame.count)
                                  .arg(s.frame.median, 0, 'f', 1)
                                  .arg(s.frame.p10, 0, 'f', 1)
                                  .arg(s.frame.p90, 0, 'f', 1),
                              0);
        } else if (side == m_selected || m_compare) {
            m_views[index(side)]->redrawForMeasurement();
        }
    }
}

void MainWindow::showFrameTimes()
{
    std::vector<FrameTimeHistory::Summary> sides{m_history[0].summary()};
    if (m_compare)
        sides.push_back(m_history[1].summary());
    const Renderer* renderer = m_views[0]->renderer();
    m_accuracyDock->setFrameTimes(sides, renderer && isSoftwareRenderer(renderer->rendererString()));
}

QString MainWindow::timingText(Side side) const
{
    const Renderer* renderer = m_views[index(side)]->renderer();
    if (!renderer)
        return QString();
    const std::optional<Settings>& shown = m_views[index(side)]->renderedSettings();
    return FrameTimeHistory::text(m_history[index(side)].summary(), isSoftwareRenderer(renderer->rendererString()),
                                  !shown || shown->shadow.enabled);
}

QString MainWindow::compareTimingText() const
{
    if (!m_compare)
        return timingText(m_selected);
    // Both sides' frame and what B costs more (or less) than A, short enough for the default
    // window: the passes of each are in the tooltip and in the accuracy dock's cost table.
    const FrameTimeHistory::Summary a = m_history[0].summary(), b = m_history[1].summary();
    if (a.frame.count == 0 || b.frame.count == 0)
        return QString();
    const Renderer* renderer = m_views[0]->renderer();
    const bool cpu = renderer && isSoftwareRenderer(renderer->rendererString());
    // As the accuracy dock: no difference until each side has frames enough to tell one.
    constexpr int enough = AccuracyMetricsPanel::kFramesToCompare;
    if (a.frame.count < enough || b.frame.count < enough)
        return tr("frame A: %1 · B: %2 · measuring (%3 and %4 of %5 frames)")
            .arg(a.frame.median, 0, 'f', 1)
            .arg(b.frame.median, 0, 'f', 1)
            .arg(a.frame.count)
            .arg(b.frame.count)
            .arg(enough);
    return tr("frame A: %1 · B: %2 · B − A: %3 ms%4 · medians")
        .arg(a.frame.median, 0, 'f', 1)
        .arg(b.frame.median, 0, 'f', 1)
        .arg(b.frame.median - a.frame.median, 0, 'f', 1)
        .arg(cpu ? tr(" CPU") : QString());
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

QString MainWindow::timingToolTip() const
{
    const QString about = tr("Medians over the last frames of the wall time of the shadow pass (over the frames that ran it; \"cached\" "
                             "when the light, the casters and the map did not change), the lit pass and the whole frame, each between "
                             "glFinish calls; on a software renderer (llvmpipe) that is CPU time (\"CPU\"). View → Measure 100 "
                             "Frames times the pass on every frame.");
    const auto side = [this](Side side) {
        const std::optional<Settings>& shown = m_views[index(side)]->renderedSettings();
        return FrameTimeHistory::explanation(m_history[index(side)].summary(), !shown || shown->shadow.enabled);
    };
    if (!m_compare)
        return tr("%1\n\n%2").arg(side(Side::A), about);
    return tr("Side A: %1 %2\nSide B: %3 %4\n\n%5").arg(timingText(Side::A), side(Side::A), timingText(Side::B), side(Side::B), about);
}

void MainWindow::createStatusBar()
{
    m_texelLabel = new QLabel;
    m_texelLabel->setObjectName(QStringLiteral("texelLabel"));
    m_timingLabel = new QLabel;
    m_timingLabel->setObjectName(QStringLiteral("timingLabel"));
    m_timingLabel->setToolTip(timingToolTip());
    m_mapLabel = new QLabel;
    m_mapLabel->setObjectName(QStringLiteral("mapLabel"));
    m_mapLabel->setToolTip(tr("Shadow-map size, and the footprint of one of its texels in world units: the size of the blocks in a hard shadow"));
    m_texelLabel->setToolTip(tr("The shadow-map texel under the pointer in the depth-map view: its position, depth and distance from the light"));
    // Apart enough to read as three facts, not one run-on line.
    for (QLabel* label : {m_texelLabel, m_timingLabel, m_mapLabel})
        label->setContentsMargins(12, 0, 0, 0);
    // While a file is read in the background: what, how far, and a way to stop it.
    m_openBox = new QWidget;
    m_openBox->setObjectName(QStringLiteral("openSceneProgress"));
    auto* openLayout = new QHBoxLayout(m_openBox);
    openLayout->setContentsMargins(0, 0, 0, 0);
    m_openLabel = new QLabel;
    m_openProgress = new QProgressBar;
    m_openProgress->setRange(0, 100);
    m_openProgress->setMaximumWidth(140);
    m_openCancel = new QPushButton(tr("Cancel"));
    m_openCancel->setObjectName(QStringLiteral("cancelOpenButton"));
    m_openCancel->setToolTip(tr("Stop reading the file; the current scene stays (Esc)"));
    m_openCancel->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(m_openCancel, &QPushButton::clicked, m_opener, &SceneOpener::cancel);
    openLayout->addWidget(m_openLabel);
    openLayout->addWidget(m_openProgress);
    openLayout->addWidget(m_openCancel);
    m_openBox->setVisible(false);
    statusBar()->addWidget(m_openBox);
    connect(m_opener, &SceneOpener::progressed, m_openProgress, [this](double fraction) { m_openProgress->setValue(int(fraction * 100.0 + 0.5)); });
    connect(m_opener, &SceneOpener::started, this, [this](const QString& path) {
        m_openLabel->setText(tr("Opening %1…").arg(QFileInfo(path).fileName()));
        m_openLabel->setToolTip(path);
        m_openProgress->setValue(0);
        m_openBox->setVisible(true);
        if (m_persistence == Persistence::Restore)
            m_autosave->setOpening(QFileInfo(path).absoluteFilePath());
    });
    // Messages on the left, over the room the permanent labels leave, ending in "…" with the
    // whole in the tooltip where they do not fit (a QStatusBar message is cut mid-word).
    m_messageLabel = new ElidedLabel;
    m_messageLabel->setObjectName(QStringLiteral("statusMessage"));
    statusBar()->addWidget(m_messageLabel, 1);
    m_messageTimer.setSingleShot(true);
    connect(&m_messageTimer, &QTimer::timeout, this, [this] { m_messageLabel->setFullText({}); });
    statusBar()->addPermanentWidget(m_texelLabel);
    statusBar()->addPermanentWidget(m_timingLabel);
    statusBar()->addPermanentWidget(m_mapLabel);
}

void MainWindow::showStatusMessage(const QString& text, int timeoutMs)
{
    m_messageLabel->setFullText(text);
    if (timeoutMs > 0)
        m_messageTimer.start(timeoutMs);
    else
        m_messageTimer.stop();
}

QString MainWindow::statusMessage() const
{
    return m_messageLabel->fullText();
}

QAction* MainWindow::action(const QString& objectName) const
{
    return findChild<QAction*>(objectName);
}

QString MainWindow::openScene(const QString& path)
{
    QStringList warnings;
    try {
        Settings probe;
        applySetting(probe, QStringLiteral("scene"), path);
        const Settings loaded = presetSettings(probe.scene);   // imports (cached) or throws
        if (!isPresetName(loaded.scene))
            warnings = loadSceneFile(loaded.scene)->warnings;
        setSettings(m_selected, movedToScene(m_settings[index(m_selected)], loaded), tr("Open %1").arg(QFileInfo(path).fileName()));
    } catch (const SettingsError& e) {
        return QString::fromUtf8(e.what());
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_recentScenes.removeAll(absolute);
    m_recentScenes.prepend(absolute);
    while (m_recentScenes.size() > kMaxRecentScenes)
        m_recentScenes.removeLast();
    updateRecentMenu();
    if (!warnings.isEmpty())
        showStatusMessage(tr("%1: %2").arg(QFileInfo(path).fileName(), warnings.join(QStringLiteral("; "))), 15000);
    return QString();
}

void MainWindow::openSceneReporting(const QString& path)
{
    openSceneInBackground(path);
}

void MainWindow::openSceneInBackground(const QString& path)
{
    m_pendingRestore = {};      // the user's choice wins over a restore still reading
    m_restoreQueue.clear();
    m_opener->open(path);
}

void MainWindow::showOpenError(const QString& error)
{
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), tr("%1\n\nThe current scene stays.").arg(error),
                                QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("openErrorBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::sceneOpenFinished(const QString& path, const QString& error, bool cancelled)
{
    m_openBox->setVisible(false);
    if (m_persistence == Persistence::Restore)
        m_autosave->setOpening({});
    const QString name = QFileInfo(path).fileName();
    if (m_restoreQueue.contains(path)) {
        // A scene of the restored session: its sides take their saved settings.
        m_restoreQueue.removeAll(path);
        for (std::size_t i = 0; i < 2; ++i) {
            if (!m_pendingRestore[i] || m_pendingRestore[i]->scene != path)
                continue;
            if (error.isEmpty() && !cancelled) {
                m_settings[i] = *m_pendingRestore[i];
                m_settings[1 - i].camera = m_settings[i].camera;
                if (m_persistence == Persistence::Restore) {
                    m_openingScene = path;      // suspect until drawn, as a scene the user opens
                    m_autosave->setOpening(path);
                }
            }
            m_pendingRestore[i].reset();
        }
        pushSettings();
        m_dock->setSettings(m_settings[index(m_selected)]);
        if (!error.isEmpty())
            showStatusMessage(tr("The last session's scene cannot be read: %1 — showing the default scene").arg(error), 15000);
        if (!m_restoreQueue.isEmpty())
            m_opener->open(m_restoreQueue.first());
        return;
    }
    if (cancelled) {
        showStatusMessage(tr("Cancelled: %1 not opened").arg(name), 8000);
        return;
    }
    const QString failure = error.isEmpty() ? openScene(path) : error;
    if (!failure.isEmpty()) {
        showOpenError(failure);
        return;
    }
    if (m_persistence == Persistence::Restore) {
        // Suspect until its first frame is drawn: a crash before that does not reopen it.
        m_openingScene = m_settings[index(m_selected)].scene;
        m_autosave->setOpening(m_openingScene);
        m_autosave->flush();
    }
}

void MainWindow::openSceneInteractively()
{
    QStringList patterns;
    for (const QString& suffix : modelSuffixes())
        patterns << QStringLiteral("*.") + suffix;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Scene"), m_recentScenes.isEmpty() ? QDir::homePath() : QFileInfo(m_recentScenes.first()).path(),
        tr("Models and scene files (%1 *.json);;All files (*)").arg(patterns.join(QLatin1Char(' '))));
    if (!path.isEmpty())
        openSceneReporting(path);
}

void MainWindow::updateRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    for (const QString& path : m_recentScenes)
        m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] { openSceneReporting(path); })->setToolTip(path);
    m_recentMenu->setEnabled(!m_recentScenes.isEmpty());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().size() == 1 && event->mimeData()->urls().first().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !urls.first().isLocalFile())
        return;
    event->acceptProposedAction();
    openSceneReporting(urls.first().toLocalFile());
}

namespace {

// The keys whose values differ between `a` and `b`, the camera's left out: it is the view's.
QStringList changedKeys(const Settings& a, const Settings& b)
{
    QStringList keys;
    for (const SettingKey& key : settingKeys()) {
        if (!key.key.startsWith(u"camera.") && settingValue(a, key.key) != settingValue(b, key.key))
            keys << key.key;
    }
    return keys;
}

} // namespace

void MainWindow::setSettings(Side side, const Settings& settings, const QString& undoText)
{
    ensureValid(settings);
    const SettingsChange::Sides before = setSide(side, settings);
    pushSettings();
    m_dock->setSettings(m_settings[index(m_selected)]);
    recordChange(before, side, undoText);
}

SettingsChange::Sides MainWindow::setSide(Side side, const Settings& settings)
{
    const std::size_t i = index(side), other = 1 - i;
    SettingsChange::Sides before;
    before[i] = m_settings[i];
    // One scene for both sides: the other follows onto a new one with its techniques kept,
    // in the same undo step; where they do not fit the scene's light it takes this side's.
    if (settings.scene != m_settings[i].scene && m_settings[other].scene != settings.scene) {
        before[other] = m_settings[other];
        try {
            // The light and camera as this side has them; world-unit lengths from the scene's
            // defaults where this side measures its bias in another unit.
            Settings scene = settings;
            if (scene.bias.space != BiasSpace::World)
                scene.bias = presetSettings(settings.scene).bias;
            m_settings[other] = movedToScene(m_settings[other], scene);
            ensureValid(m_settings[other]);
        } catch (const SettingsError&) {
            m_settings[other] = settings;
        }
    }
    m_settings[i] = settings;
    m_settings[other].camera = settings.camera;
    return before;
}

void MainWindow::applyEdit(const Settings& settings)
{
    const SettingsChange::Sides before = setSide(m_selected, settings);
    pushSettings();
    // Name the dock's two whole-side edits in the Edit menu; one key names itself ("Set bias.slope").
    QString text;
    const bool wholeSide = changedKeys(*before[index(m_selected)], settings).size() > 1 || before[1 - index(m_selected)];
    if (wholeSide && settings.scene != before[index(m_selected)]->scene) {
        text = tr("Choose scene %1").arg(QFileInfo(settings.scene).fileName());
    } else if (wholeSide) {
        try {
            Settings defaults = presetSettings(settings.scene);
            defaults.camera = settings.camera;
            if (settings == defaults)
                text = tr("Reset to defaults");
        } catch (const SettingsError&) {
            // a scene file that went away: the generic name will do
        }
    }
    recordChange(before, m_selected, text, true);
}

void MainWindow::recordChange(const SettingsChange::Sides& before, Side side, QString text, bool mayMerge)
{
    SettingsChange::Sides after;
    QStringList keys;
    for (std::size_t i = 0; i < 2; ++i) {
        if (!before[i])
            continue;
        after[i] = m_settings[i];
        for (const QString& key : changedKeys(*before[i], m_settings[i])) {
            if (!keys.contains(key))
                keys << key;
        }
    }
    if (keys.isEmpty())
        return;     // the camera alone, or nothing at all
    int mergeKey = -1;
    if (keys.size() == 1) {
        if (text.isEmpty())
            text = tr("Set %1").arg(keys.first());
        if (mayMerge) {
            const std::vector<SettingKey>& table = settingKeys();
            mergeKey = int(std::find_if(table.begin(), table.end(), [&](const SettingKey& k) { return k.key == keys.first(); }) - table.begin());
        }
    } else if (text.isEmpty()) {
        text = tr("Change %1 settings").arg(keys.size());
    }
    m_undoStacks[index(side)]->push(new SettingsChange(text, before, after, mergeKey, m_gesture,
                                                      [this](const SettingsChange::Sides& target, const SettingsChange::Sides& from) {
                                                          showUndoState(target, from);
                                                      }));
}

void MainWindow::showUndoState(const SettingsChange::Sides& target, const SettingsChange::Sides& from)
{
    std::array<Settings, 2> next = m_settings;
    for (std::size_t i = 0; i < 2; ++i) {
        if (!target[i])
            continue;
        Settings s = *target[i];
        // The view stays where the user looks from, unless the step changes the scene: the
        // camera then goes back with it.
        if (!from[i] || from[i]->scene == s.scene)
            s.camera = m_settings[i].camera;
        // A light the animation moved since keeps its place unless this step moved it.
        if (from[i] && from[i]->light.position == s.light.position)
            s.light.position = m_settings[i].light.position;
        try {
            ensureValid(s);
        } catch (const SettingsError&) {
            s.light.position = target[i]->light.position;   // the animated position does not fit the restored volume
        }
        next[i] = s;
    }
    m_settings = next;
    m_settings[0].camera = m_settings[1].camera = next[index(m_selected)].camera;  // one camera for both sides
    pushSettings();
    m_dock->setSettings(m_settings[index(m_selected)]);
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event)
{
    // A number field of a dock would take Ctrl+Z for its own text; its value is applied on
    // Enter, so what the user means is the window's undo. Left unaccepted, the override lets
    // the Edit menu's shortcut run.
    if (event->type() == QEvent::ShortcutOverride && m_undoAction) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const QKeySequence pressed(key->keyCombination());
        const bool undoKey = m_undoAction->shortcuts().contains(pressed) || m_redoAction->shortcuts().contains(pressed);
        auto* widget = qobject_cast<QWidget*>(watched);
        // The line edit first, then (the override travels up) its spin box, which would hand
        // it to the line edit again.
        const bool numberField = widget && (qobject_cast<QAbstractSpinBox*>(widget) || qobject_cast<QAbstractSpinBox*>(widget->parentWidget()));
        if (undoKey && numberField && (m_dock->isAncestorOf(widget) || m_accuracyDock->isAncestorOf(widget)))
            return true;
    }
    // A new press starts a new gesture; a key's auto-repeat continues the one it began.
    if (event->type() == QEvent::MouseButtonPress
        || (event->type() == QEvent::KeyPress && !static_cast<QKeyEvent*>(event)->isAutoRepeat()))
        ++m_gesture;
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::turnLight(double azimuthDegrees, double elevationDegrees)
{
    // As the dock's direction fields edit it: one drag is one undo step ("Set light.position").
    Settings turned = m_settings[index(m_selected)];
    LightAngles angles = lightAngles(turned.light.position, turned.light.target, m_lightAzimuth);
    angles.azimuth = std::remainder(angles.azimuth + azimuthDegrees, 360.0);
    // Short of the pole, so the next drag still knows which way round it is.
    angles.elevation = std::clamp(angles.elevation + elevationDegrees, -89.5, 89.5);
    m_lightAzimuth = angles.azimuth;
    turned.light.position = lightPosition(turned.light.target, angles);
    try {
        ensureValid(turned);
    } catch (const SettingsError& e) {
        showStatusMessage(tr("Cannot turn the light there: %1").arg(QString::fromUtf8(e.what())), 8000);
        return;
    }
    applyEdit(turned);
    m_dock->updateFrom(turned, {QStringLiteral("light.position")});
}

void MainWindow::setCamera(const CameraSettings& camera)
{
    for (Settings& s : m_settings)
        s.camera = camera;
    m_dock->updateFrom(m_settings[index(m_selected)], {});
    pushSettings();
}

void MainWindow::pushSettings()
{
    if (m_densityAction) {
        const QSignalBlocker block(m_densityAction);
        m_densityAction->setChecked(m_settings[index(m_selected)].shading.texelDensity);
    }
    for (std::size_t i = 0; i < 2; ++i)
        m_views[i]->setSettings(m_settings[i]);
    m_accuracyDock->setSides(m_settings[0], m_compare ? std::optional(m_settings[1]) : std::nullopt, int(index(m_selected)));
    updateCaptions();
    sessionChanged();
}

void MainWindow::updateCaptions()
{
    for (std::size_t i = 0; i < 2; ++i) {
        m_scenePanes[i]->setHighlighted(m_compare && index(m_selected) == i);
        m_scenePanes[i]->setCaption(m_compare ? tr("Side %1").arg(QLatin1String(kSideNames[i])) : tr("Scene"),
                                    settingsSummary(m_settings[i]));
    }
    const Settings& shown = m_settings[index(m_selected)];
    // What the map holds: depth in its format, or a moment technique's moments.
    const bool moments = isMomentTechnique(shown.filter.mode);
    const QString holds = moments ? tr("moments RGBA%1F").arg(toString(shown.moments.format)) : toString(shown.map.format);
    const QString light = tr("%1 light, %2").arg(toString(shown.light.projection), holds);
    m_depthPane->setCaption(m_compare ? tr("Shadow map of %1").arg(QLatin1String(kSideNames[index(m_selected)])) : tr("Shadow map"),
                            shown.shadow.enabled ? light : tr("shadows are off"));
}

void MainWindow::updateStatus()
{
    const SceneView* view = m_views[index(m_selected)];
    const Renderer* renderer = view->renderer();
    if (!renderer || !view->renderedSettings())
        return;
    const FrameStats& stats = renderer->lastFrame();
    const Settings& shown = *view->renderedSettings();
    // Wall times with glFinish between passes (the GPU timer misses a software renderer's
    // deferred rasterisation), as medians over the last frames: single frames jump under load.
    m_timingLabel->setText(compareTimingText());
    m_timingLabel->setToolTip(timingToolTip());
    // Short enough for the default window; the tooltip says it in full.
    const bool refitted = stats.lightFitted && stats.texelWorldSizeBeforeFit != stats.texelWorldSize;
    const QString footprint = tr("texel footprint %1 wu").arg(stats.texelWorldSize, 0, 'g', 3);
    const QString mapName = shown.shadow.virtualMap ? tr("virtual map, %1 pages").arg(stats.virtualPages.resident) : tr("map %1").arg(squareSize(shown.map.size));
    m_mapLabel->setText(shown.shadow.enabled ? tr("%1 · %2").arg(mapName, footprint) : tr("no shadow map"));
    QString mapTip = tr("Shadow-map size, and the footprint of one of its texels in world units: the size of the blocks in a hard shadow.");
    if (shown.shadow.enabled && refitted)
        mapTip += QLatin1Char(' ') + tr("Fitted to the scene: %1 wu a texel, against %2 wu with the volume as set.")
                                         .arg(stats.texelWorldSize, 0, 'g', 3)
                                         .arg(stats.texelWorldSizeBeforeFit, 0, 'g', 3);
    if (const QString warp = warpStatusText(stats); shown.shadow.enabled && !warp.isEmpty())
        mapTip += QLatin1Char(' ') + warp + QLatin1Char('.');
    if (const QString pages = virtualMapStatusText(stats); shown.shadow.enabled && !pages.isEmpty())
        mapTip += QLatin1Char(' ') + pages + QLatin1Char('.');
    m_mapLabel->setToolTip(mapTip);
}

void MainWindow::setCompareMode(bool on)
{
    if (on == m_compare)
        return;
    m_compare = on;
    {
        const QSignalBlocker block(m_compareAction);
        m_compareAction->setChecked(on);
    }
    m_copyAction->setEnabled(on);
    m_swapAction->setEnabled(on);
    m_scenePanes[1]->setVisible(on);
    // Two scene views need the room more than the depth map does.
    const int total = m_mainSplitter->width();
    m_mainSplitter->setSizes(on ? QList<int>{total * 3 / 4, total / 4} : QList<int>{total * 3 / 5, total * 2 / 5});
    if (on) {
        const int half = std::max(1, m_sceneSplitter->width() / 2);
        m_sceneSplitter->setSizes({half, half});
    }
    selectSide(on ? m_selected : Side::A);
    showFrameTimes();
}

void MainWindow::selectSide(Side side)
{
    if (!m_compare)
        side = Side::A;
    m_selected = side;
    m_dock->setSettings(m_settings[index(side)]);
    m_accuracyDock->setSides(m_settings[0], m_compare ? std::optional(m_settings[1]) : std::nullopt, int(index(side)));
    m_dock->setSideName(m_compare ? QLatin1String(kSideNames[index(side)]) : QString());
    // Tabbed or floating, a dock says whose settings it holds.
    m_dock->setWindowTitle(m_compare ? tr("Properties — side %1").arg(QLatin1String(kSideNames[index(side)])) : tr("Properties"));
    m_accuracyDock->setWindowTitle(m_compare ? tr("Accuracy — A and B") : tr("Accuracy"));
    m_undoGroup->setActiveStack(m_undoStacks[index(side)]);
    m_depthView->setSource(m_views[index(side)]);
    updateCaptions();
    updateStatus();
    sessionChanged();
}

void MainWindow::copyAToB()
{
    const SettingsChange::Sides before{std::nullopt, m_settings[1]};
    m_settings[1] = m_settings[0];
    pushSettings();
    m_dock->setSettings(m_settings[index(m_selected)]);
    recordChange(before, m_selected, tr("Copy A → B"));
}

void MainWindow::swapSides()
{
    const SettingsChange::Sides before{m_settings[0], m_settings[1]};
    std::swap(m_settings[0], m_settings[1]);
    pushSettings();
    m_dock->setSettings(m_settings[index(m_selected)]);
    recordChange(before, m_selected, tr("Swap A ↔ B"));
}

void MainWindow::setLightAnimation(bool animate, double degreesPerSecond)
{
    m_animationSpeed = degreesPerSecond;
    m_dock->setAnimation(animate, degreesPerSecond);
    {
        const QSignalBlocker block(m_animateAction);
        m_animateAction->setChecked(animate);
    }
    if (animate && !m_animationTimer.isActive()) {
        m_animationClock.start();
        m_animationTimer.start();
    } else if (!animate) {
        m_animationTimer.stop();
    }
}

void MainWindow::animateLight()
{
    // Turn by elapsed time, not by tick, so the speed holds when frames are slow.
    const double seconds = double(m_animationClock.restart()) * 1e-3;
    const double angle = glm::radians(m_animationSpeed * seconds);
    const double c = std::cos(angle), s = std::sin(angle);
    for (Settings& settings : m_settings) {
        const glm::dvec3 offset = settings.light.position - settings.light.target;
        settings.light.position = settings.light.target + glm::dvec3(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
    }
    m_dock->updateFrom(m_settings[index(m_selected)], {QStringLiteral("light.position")});
    pushSettings();
}

QString MainWindow::saveScreenshot(ScreenshotDialog::Target target, const QString& path)
{
    QImage image;
    switch (target) {
    case ScreenshotDialog::Target::SceneView:
        image = m_views[index(m_selected)]->grabFramebuffer();
        break;
    case ScreenshotDialog::Target::DepthMapView:
        image = m_depthView->grabFramebuffer();
        break;
    case ScreenshotDialog::Target::Window:
        image = grab().toImage();
        break;
    }
    if (image.isNull())
        return tr("There is nothing to capture: the view has no size.");
    try {
        checkOutputFile(path, tr("Screenshot"));
        writeOutputFile(path, encodePng(image.convertToFormat(QImage::Format_RGB32)));
    } catch (const OutputError& e) {
        return QString::fromStdString(e.what());
    }
    showStatusMessage(tr("Saved %1 (%2×%3)").arg(QDir::toNativeSeparators(path)).arg(image.width()).arg(image.height()), 8000);
    return QString();
}

QString MainWindow::screenshotFolder()
{
    // The last folder used while it exists; else the pictures folder, made if missing (a
    // fresh account has none); else the home folder.
    if (!m_screenshotFolder.isEmpty() && QFileInfo(m_screenshotFolder).isDir())
        return m_screenshotFolder;
    const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    if (!pictures.isEmpty() && QDir().mkpath(pictures) && QFileInfo(pictures).isDir() && QFileInfo(pictures).isWritable())
        return pictures;
    return QDir::homePath();
}

void MainWindow::saveScreenshotInteractively()
{
    const QString name = screenshotFileName(m_settings[index(m_selected)], QDateTime::currentDateTime());
    ScreenshotDialog dialog(QDir(screenshotFolder()).filePath(name), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_screenshotFolder = QFileInfo(dialog.path()).absolutePath();
    const QString error = saveScreenshot(dialog.target(), dialog.path());
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Save Screenshot"), error);
}

QString MainWindow::exportSettings(const QString& path) const
{
    try {
        saveSettingsFile(path, m_settings[index(m_selected)]);
    } catch (const OutputError& e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

QString MainWindow::importSettings(const QString& path)
{
    try {
        // Keys the file leaves out keep their current values, as with --settings on the CLI.
        const Settings settings = loadSettingsFile(path, m_settings[index(m_selected)]);
        setSettings(m_selected, settings, tr("Import %1").arg(QFileInfo(path).fileName()));
    } catch (const SettingsError& e) {
        return QString::fromStdString(e.what());
    }
    showStatusMessage(tr("Imported %1").arg(QDir::toNativeSeparators(path)), 8000);
    return QString();
}

void MainWindow::exportSettingsInteractively()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Settings"),
                                                      QDir(screenshotFolder()).filePath(QStringLiteral("shadowlab-settings.json")),
                                                      tr("ShadowLab settings (*.json)"));
    if (path.isEmpty())
        return;
    const QString error = exportSettings(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export Settings"), error);
    else
        showStatusMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 8000);
}

void MainWindow::importSettingsInteractively()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Settings"), screenshotFolder(), tr("ShadowLab settings (*.json)"));
    if (path.isEmpty())
        return;
    const QString error = importSettings(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Import Settings"), error);
}

void MainWindow::showArtifactsHelp()
{
    auto* help = findChild<ArtifactsHelp*>();
    if (!help) {
        help = new ArtifactsHelp(this);
        connect(help, &ArtifactsHelp::presetRequested, m_dock, &PropertiesDock::applyPreset);
    }
    help->show();
    help->raise();
}

void MainWindow::showAbout()
{
    const SceneView* view = m_views[0];
    const QString renderer = view->renderer() ? view->renderer()->rendererString() : tr("no OpenGL context yet");
    QMessageBox::about(this, tr("About ShadowLab"),
                       tr("<h3>ShadowLab %1</h3><p>An explorer for shadow mapping: every parameter of the technique "
                          "on a slider, beside the light's depth map, with the cost of each pass.</p>"
                          "<p>Renderer: %2</p><p>Built with Qt %3.</p>")
                           .arg(QCoreApplication::applicationVersion(), renderer.toHtmlEscaped(), QString::fromLatin1(qVersion())));
}

void MainWindow::restoreLayout()
{
    QSettings store;
    if (const QByteArray geometry = store.value(QStringLiteral("window/geometry")).toByteArray(); !geometry.isEmpty())
        restoreGeometry(geometry);
    if (const QByteArray state = store.value(QStringLiteral("window/state")).toByteArray(); !state.isEmpty())
        QMainWindow::restoreState(state);
    if (const QByteArray splitter = store.value(QStringLiteral("window/splitter")).toByteArray(); !splitter.isEmpty())
        m_mainSplitter->restoreState(splitter);
    m_recentScenes = store.value(QStringLiteral("scenes/recent")).toStringList();
    updateRecentMenu();
    m_volumeAction->setChecked(store.value(QStringLiteral("view/lightVolume"), true).toBool());
    m_screenshotFolder = store.value(QStringLiteral("view/screenshotFolder"), m_screenshotFolder).toString();
}

QVariantMap MainWindow::savedSession() const
{
    QSettings store;
    QVariantMap session;
    for (const QString& key : {QStringLiteral("settings/A"), QStringLiteral("settings/B"), QStringLiteral("view/compare"), QStringLiteral("view/selected")})
        session.insert(key, store.value(key));
    return session;
}

void MainWindow::restoreSession(const QVariantMap& session, const QString& skipScene)
{
    // A file the user is opening now wins over the session's files.
    const bool userOpening = m_opener->isBusy() && !m_restoreQueue.contains(m_opener->path());
    for (std::size_t i = 0; i < 2; ++i) {
        const std::optional<Settings> settings = settingsFromText(session.value(QStringLiteral("settings/%1").arg(QLatin1String(kSideNames[i]))).toString());
        if (!settings || (!skipScene.isEmpty() && settings->scene == skipScene))
            continue;
        if (isPresetName(settings->scene)) {
            m_settings[i] = *settings;
        } else if (!userOpening) {
            m_pendingRestore[i] = settings;
            if (!m_restoreQueue.contains(settings->scene))
                m_restoreQueue << settings->scene;
        }
    }
    m_settings[1].camera = m_settings[0].camera;
    setCompareMode(session.value(QStringLiteral("view/compare"), false).toBool());
    m_selected = session.value(QStringLiteral("view/selected")).toString() == u"B" ? Side::B : Side::A;
    if (!m_restoreQueue.isEmpty())
        m_opener->open(m_restoreQueue.first());
}

void MainWindow::offerRestore(const QString& openingAtCrash)
{
    auto* box = new QMessageBox(this);
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
        m_holdAutosave = false;
        if (button == restore) {
            restoreSession(session, openingAtCrash);
            pushSettings();
            selectSide(m_selected);
        }
        sessionChanged();
    });
    box->open();
}

void MainWindow::saveState() const
{
    QSettings store;
    store.setValue(QStringLiteral("window/geometry"), saveGeometry());
    store.setValue(QStringLiteral("window/state"), QMainWindow::saveState());
    store.setValue(QStringLiteral("window/splitter"), m_mainSplitter->saveState());
    store.setValue(QStringLiteral("scenes/recent"), m_recentScenes);
    for (std::size_t i = 0; i < 2; ++i)
        store.setValue(QStringLiteral("settings/%1").arg(QLatin1String(kSideNames[i])), settingsAsText(m_pendingRestore[i].value_or(m_settings[i])));
    store.setValue(QStringLiteral("view/lightVolume"), m_volumeAction->isChecked());
    store.setValue(QStringLiteral("view/screenshotFolder"), m_screenshotFolder);
    store.setValue(QStringLiteral("view/compare"), m_compare);
    store.setValue(QStringLiteral("view/selected"), QLatin1String(kSideNames[index(m_selected)]));
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    m_opener->cancel();
    if (m_persistence == Persistence::Restore)
        m_autosave->end();
    QMainWindow::closeEvent(event);
}

} // namespace shadowlab
