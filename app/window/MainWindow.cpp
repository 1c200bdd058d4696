#include "MainWindow.h"

#include "AccuracyDock.h"
#include "Application.h"
#include "ArtifactsHelp.h"
#include "DepthMapView.h"
#include "LightAnimation.h"
#include "TimelineBar.h"
#include "Loupe.h"
#include "PropertiesDock.h"
#include "Renderer.h"
#include "SceneFileWatcher.h"
#include "SceneLibrary.h"
#include "SceneView.h"
#include "SettingsError.h"
#include "SettingsSummary.h"
#include "TimingController.h"
#include "ViewPane.h"
#include "WheelGuard.h"

#include <QAction>
#include <QCoreApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace shadowlab {

namespace {

const char* const kSideNames[] = {"A", "B"};

std::size_t index(MainWindow::Side side)
{
    return std::size_t(side);
}

} // namespace

MainWindow::MainWindow(Persistence persistence, QWidget* parent) : QMainWindow(parent), m_persistence(persistence)
{
    setWindowTitle(tr("ShadowLab"));
    setAcceptDrops(true);   // a model or scene file dropped anywhere on the window, the views included
    createViews();
    createControllers();
    createDocks();
    createActions();
    createMeasureActions();
    createToolBar();
    createMenus();
    createStatusBar();
    resize(1200, 750);
    // The dock as narrow as its fields read well: the views are what the window is for.
    resizeDocks({m_dock}, {400}, Qt::Horizontal);
    m_mainSplitter->setSizes({480, 320});
    m_session->start(m_mainSplitter, m_volumeAction, {m_dock, m_accuracyDock});
    pushSettings();
    selectSide(selectedSide());
}

MainWindow::~MainWindow() = default;

void MainWindow::createViews()
{
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
        connect(m_views[i], &SceneView::wipeSideActivated, this, [this] { selectSide(Side::B); });
        connect(m_views[i], &SceneView::frameRendered, this, [this, side] { frameRendered(side); });
        connect(m_views[i], &SceneView::renderFailed, this, [this, side](const QString& key, const QString& message) {
            if (side == selectedSide())
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
    // The timeline under the views (not a window-wide toolbar: the docks keep their height).
    m_timeline = new TimelineBar;
    auto* central = new QWidget;
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    column->addWidget(m_mainSplitter, 1);
    column->addWidget(m_timeline);
    setCentralWidget(central);
}

void MainWindow::createControllers()
{
    m_undo = new UndoController([this](const SettingsChange::Sides& target, const SettingsChange::Sides& from) { showUndoState(target, from); },
                                this);
    m_timing = new TimingController(m_sides, m_views, this);
    connect(m_timing, &TimingController::frameRecorded, this, &MainWindow::showFrameTimes);
    connect(m_timing, &TimingController::message, this, &MainWindow::showStatusMessage);
    m_import = new ImportController(this, m_sides, [this](const Settings& settings, const QString& undoText) {
        setSettings(selectedSide(), framedForView(settings), undoText);
    });
    m_session = new PersistenceController(*this, m_sides, *m_import, m_persistence == Persistence::Restore);
    connect(m_import, &ImportController::restoredSidesChanged, this, &MainWindow::showSides);
    connect(m_import, &ImportController::message, this, &MainWindow::showStatusMessage);
    // A shown file saved again (by a modelling tool) is read again and drawn with the settings as
    // they are.
    m_fileWatcher = new SceneFileWatcher(this);
    connect(m_fileWatcher, &SceneFileWatcher::changed, m_import, &ImportController::reload);
    connect(m_import, &ImportController::sceneReloaded, this, [this] {
        m_sizedScene.clear();   // the dock's sliders, object lists and clip follow the new contents
        m_accuracyDock->sceneContentsChanged();
        for (SceneView* view : m_views)
            view->update();
    });
    connect(m_session, &PersistenceController::message, this, &MainWindow::showStatusMessage);
    connect(m_session, &PersistenceController::sessionRestored, this, [this] {
        pushSettings();
        selectSide(selectedSide());
    });
}

void MainWindow::createDocks()
{
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
            [this](int side, const QImage& image) {
                m_views[std::size_t(side)]->setErrorOverlay(image);
                if (side == 1)
                    m_views[0]->setWipeOverlay(image);     // shown while wiping, right of the divider
            });
    connect(m_accuracyDock, &AccuracyDock::applySettingsRequested, this, [this](const Settings& settings) {
        try {
            setSettings(selectedSide(), settings, tr("Apply measured configuration"));
        } catch (const SettingsError& e) {
            showStatusMessage(tr("Cannot apply that configuration: %1").arg(QString::fromUtf8(e.what())), 8000);
        }
    });
    // A model's bias, tuned as it opens (once the dock has its settings), is one undo step.
    connect(m_import, &ImportController::fileOpened, this, [this] { QTimer::singleShot(0, m_accuracyDock, &AccuracyDock::tuneForOpenedModel); });
    connect(m_accuracyDock, &AccuracyDock::tunedBiasRequested, this, [this](const Settings& settings) {
        try {
            setSettings(selectedSide(), settings, tr("Tune bias for the model"));
        } catch (const SettingsError& e) {
            showStatusMessage(tr("Cannot apply the tuned bias: %1").arg(QString::fromUtf8(e.what())), 8000);
        }
    });
    connect(m_depthView, &DepthMapView::texelHovered, this, [this](const QString& text) { m_status->setTexel(text); });

    m_animation = new LightAnimation(this);
    connect(m_animation, &LightAnimation::turned, this, &MainWindow::turnLights);
    createTimeline();

    // Over the docks the wheel scrolls; a field takes it once clicked.
    WheelGuard::guardFields(m_dock);
    WheelGuard::guardFields(m_accuracyDock);
    m_undo->guardFields({m_dock, m_accuracyDock});
}

void MainWindow::frameRendered(Side side)
{
    m_timing->record(index(side), m_animation->isRunning() || (settings(side).animation.play && m_clipLength > 0.0));
    m_session->drawn(settings(side).scene);
    // Both sides are measured over side A's pixels (one reference serves both).
    if (side == Side::A)
        m_accuracyDock->setViewSize(m_views[0]->size() * m_views[0]->devicePixelRatio());
    if (side != selectedSide())
        return;
    updateStatus();
    const SceneView* view = m_views[index(side)];
    if (const Renderer* renderer = view->renderer(); renderer && view->renderedSettings()) {
        // The dock's sliders follow the size of the scene now drawn.
        if (const Scene* scene = renderer->scene(); scene && scene->name != m_sizedScene) {
            m_sizedScene = scene->name;
            m_clipLength = scene->clipLength();
            showClock();
            // A frozen frustum belongs to the scene it was frozen in.
            if (m_freezeAction && m_freezeAction->isChecked())
                m_freezeAction->setChecked(false);

            const Bounds models = scene->modelBounds();
            m_dock->setSceneSize(models.center(), glm::length(models.max - models.min) * 0.5);
            const QStringList tokens = objectTokens(*scene);
            QStringList labels;
            for (qsizetype i = 0; i < tokens.size(); ++i) {
                const QString& name = scene->objects[std::size_t(i)].name;
                labels << (!tokens[i].startsWith(u'#') ? name : name.isEmpty() ? tr("object %1").arg(i) : QStringLiteral("%1 (%2)").arg(name, tokens[i]));
            }
            m_dock->setSceneObjects(tokens, labels);
        }
        const FittedLight& fit = renderer->lastFit();
        m_dock->showFit(fit, view->renderedSettings()->light);
        const std::vector<SettingsIssue> warnings = fitWarnings(fit);
        if (!warnings.empty() && warnings.front().message != m_lastFitWarning)
            showStatusMessage(tr("Warning: %1").arg(warnings.front().message), 10000);
        m_lastFitWarning = warnings.empty() ? QString() : warnings.front().message;
        QStringList all;
        for (const SettingsIssue& issue : warnings)
            all << tr("%1: %2").arg(issue.key, issue.message);
        m_status->setWarnings(QStringLiteral("fit"), all);
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    m_import->dragEnter(event);
}

void MainWindow::dropEvent(QDropEvent* event)
{
    m_import->drop(event);
}

void MainWindow::setSettings(Side side, const Settings& settings, const QString& undoText)
{
    ensureValid(settings);
    const SettingsChange::Sides before = m_sides.set(index(side), settings);
    showSides();
    recordChange(before, side, undoText);
}

Settings MainWindow::framedForView(Settings settings) const
{
    // A scene opened or chosen, with the camera it comes with: framed for the view it is shown
    // in, whatever its shape (a camera the user set stays as it is).
    if (settings.scene != m_sides.selectedSettings().scene) {
        try {
            if (settings.camera == presetSettings(settings.scene).camera)
                settings.camera = presetCamera(settings.scene, viewAspect());
        } catch (const SettingsError&) {
            // The scene's own error is said where it is applied.
        }
    }
    return settings;
}

void MainWindow::applyEdit(const Settings& requested)
{
    const Settings settings = framedForView(requested);
    const SettingsChange::Sides before = m_sides.set(m_sides.selected(), settings);
    pushSettings();
    recordChange(before, selectedSide(), UndoController::editText(before, settings, m_sides.selected()), true);
}

void MainWindow::recordChange(const SettingsChange::Sides& before, Side side, const QString& text, bool mayMerge)
{
    m_undo->record(before, m_sides.sides(), index(side), text, mayMerge);
}

void MainWindow::showUndoState(const SettingsChange::Sides& target, const SettingsChange::Sides& from)
{
    m_sides.show(target, from);
    showSides();
}

void MainWindow::turnLight(double azimuthDegrees, double elevationDegrees)
{
    // As the dock's direction fields edit it: one drag is one undo step ("Set light.position").
    const Settings turned = m_sides.lightTurned(azimuthDegrees, elevationDegrees);
    try {
        ensureValid(turned);
    } catch (const SettingsError& e) {
        showStatusMessage(tr("Cannot turn the light there: %1").arg(QString::fromUtf8(e.what())), 8000);
        return;
    }
    applyEdit(turned);
    m_dock->updateFrom(turned, {QStringLiteral("light.position")});
}

QStringList MainWindow::warnings() const
{
    return m_status->warnings();
}

double MainWindow::viewAspect() const
{
    const SceneView* view = m_views[std::size_t(selectedSide())];
    return view != nullptr ? view->aspect() : 16.0 / 9.0;
}

void MainWindow::setCamera(const CameraSettings& camera)
{
    m_sides.setCamera(camera);
    m_dock->updateFrom(m_sides.selectedSettings(), {});
    pushSettings();
}

void MainWindow::pushSettings()
{
    if (m_densityAction) {
        const QSignalBlocker block(m_densityAction);
        m_densityAction->setChecked(m_sides.selectedSettings().shading.texelDensity);
    }
    if (m_shadowOnlyAction) {
        const QSignalBlocker block(m_shadowOnlyAction);
        m_shadowOnlyAction->setChecked(m_sides.selectedSettings().shading.shadowOnly);
    }
    for (std::size_t i = 0; i < 2; ++i)
        m_views[i]->setSettings(m_sides.settings(i));
    m_fileWatcher->watch({m_sides.settings(0).scene, m_sides.settings(1).scene});
    // A file's warnings are the file's: another scene shown (a preset, an undo) takes them off.
    if (!m_warnedScene.isEmpty() && m_sides.settings(0).scene != m_warnedScene && m_sides.settings(1).scene != m_warnedScene) {
        m_warnedScene.clear();
        m_status->setWarnings(QStringLiteral("import"), {});
    }
    if (wiping())
        m_views[0]->setWipe(m_sides.settings(1));
    m_accuracyDock->setSides(m_sides.settings(0), compareMode() ? std::optional(m_sides.settings(1)) : std::nullopt, int(m_sides.selected()));
    updateCaptions();
    showClock();
    m_session->changed();
}

void MainWindow::showSides()
{
    pushSettings();
    m_dock->setSettings(m_sides.selectedSettings());
}

void MainWindow::updateCaptions()
{
    for (std::size_t i = 0; i < 2; ++i) {
        m_scenePanes[i]->setHighlighted(compareMode() && m_sides.selected() == i);
        m_scenePanes[i]->setCaption(compareMode() ? tr("Side %1").arg(QLatin1String(kSideNames[i])) : tr("Scene"),
                                    compareMode() ? comparedSummary(m_sides.settings(i), m_sides.settings(1 - i)) : settingsSummary(m_sides.settings(i)));
    }
    // Wiping, one pane holds both sides: its caption says what differs, B's side of it.
    if (wiping())
        m_scenePanes[0]->setCaption(tr("A | B wipe"), tr("B: %1").arg(comparedSummary(m_sides.settings(1), m_sides.settings(0))));
    const Settings& shown = m_sides.selectedSettings();
    m_depthPane->setCaption(compareMode() ? tr("Shadow map of %1").arg(QLatin1String(kSideNames[m_sides.selected()])) : tr("Shadow map"),
                            shadowMapSummary(shown));
}

void MainWindow::updateStatus()
{
    const SceneView* view = m_views[m_sides.selected()];
    const Renderer* renderer = view->renderer();
    if (!renderer || !view->renderedSettings())
        return;
    // Wall times with glFinish between passes (the GPU timer misses a software renderer's
    // deferred rasterisation), as medians over the last frames: single frames jump under load.
    m_status->setTiming(m_timing->statusText(), m_timing->toolTip());
    m_status->showMap(renderer->lastFrame(), *view->renderedSettings());
}

void MainWindow::setWipe(bool on)
{
    if (on == wiping())
        return;
    if (on && !compareMode())
        setCompareMode(true);
    {
        const QSignalBlocker block(m_wipeAction);
        m_wipeAction->setChecked(on);
    }
    // One view holds both sides; B's own view rests meanwhile.
    m_scenePanes[1]->setVisible(compareMode() && !on);
    m_views[0]->setWipe(on ? std::optional(m_sides.settings(1)) : std::nullopt);
    if (on)
        m_views[0]->setWipeOverlay(m_views[1]->errorOverlay());
    updateCaptions();
}

bool MainWindow::wiping() const
{
    return m_views[0]->wiping();
}

void MainWindow::setCompareMode(bool on)
{
    if (on == compareMode())
        return;
    m_sides.setOn(on);
    {
        const QSignalBlocker block(m_compareAction);
        m_compareAction->setChecked(on);
    }
    m_copyAction->setEnabled(on);
    m_swapAction->setEnabled(on);
    if (!on)
        setWipe(false);
    m_scenePanes[1]->setVisible(on && !wiping());
    // Two scene views need the room more than the depth map does.
    const int total = m_mainSplitter->width();
    m_mainSplitter->setSizes(on ? QList<int>{total * 3 / 4, total / 4} : QList<int>{total * 3 / 5, total * 2 / 5});
    if (on) {
        const int half = std::max(1, m_sceneSplitter->width() / 2);
        m_sceneSplitter->setSizes({half, half});
    }
    selectSide(on ? selectedSide() : Side::A);
    showFrameTimes();
}

void MainWindow::selectSide(Side side)
{
    if (!compareMode())
        side = Side::A;
    m_sides.select(index(side));
    m_dock->setSettings(m_sides.settings(index(side)));
    m_accuracyDock->setSides(m_sides.settings(0), compareMode() ? std::optional(m_sides.settings(1)) : std::nullopt, int(index(side)));
    m_dock->setSideName(compareMode() ? QLatin1String(kSideNames[index(side)]) : QString());
    // Tabbed or floating, a dock says whose settings it holds.
    m_dock->setWindowTitle(compareMode() ? tr("Properties — side %1").arg(QLatin1String(kSideNames[index(side)])) : tr("Properties"));
    m_accuracyDock->setWindowTitle(compareMode() ? tr("Accuracy — A and B") : tr("Accuracy"));
    m_undo->setActiveSide(index(side));
    m_depthView->setSource(m_views[index(side)]);
    updateCaptions();
    updateStatus();
    m_session->changed();
}

void MainWindow::copyAToB()
{
    const SettingsChange::Sides before = m_sides.copyAToB();
    showSides();
    recordChange(before, selectedSide(), tr("Copy A → B"));
}

void MainWindow::swapSides()
{
    const SettingsChange::Sides before = m_sides.swap();
    showSides();
    recordChange(before, selectedSide(), tr("Swap A ↔ B"));
}

void MainWindow::setLightAnimation(bool animate, double degreesPerSecond)
{
    m_animation->setSpeed(degreesPerSecond);
    m_dock->setAnimation(animate, degreesPerSecond);
    {
        const QSignalBlocker block(m_animateAction);
        m_animateAction->setChecked(animate);
    }
    m_animation->setRunning(animate);
}

void MainWindow::createTimeline()
{
    connect(m_timeline, &TimelineBar::playToggled, this, [this](bool play) {
        Settings s = m_sides.selectedSettings();
        s.animation.play = play;
        applyEdit(s);
    });
    connect(m_timeline, &TimelineBar::ticked, this, &MainWindow::advanceClock);
    connect(m_timeline, &TimelineBar::scrubStarted, this, [this] { m_scrubStart = {m_sides.settings(0), m_sides.settings(1)}; });
    connect(m_timeline, &TimelineBar::scrubbed, this, &MainWindow::scrubTo);
    connect(m_timeline, &TimelineBar::scrubFinished, this, [this] {
        if (m_scrubStart[0] && m_scrubStart[0]->animation.time != m_sides.settings(0).animation.time)
            recordChange(m_scrubStart, selectedSide(), tr("Set scene.time"));
        m_scrubStart = {};
        showClock();    // a drag paused the clock; a playing scene plays on
    });
}

void MainWindow::advanceClock(double wallSeconds)
{
    m_sides.advanceClock(wallSeconds, m_clipLength);
    m_dock->updateFrom(m_sides.selectedSettings(), {QStringLiteral("scene.time")});
    pushSettings();
}

void MainWindow::scrubTo(double time)
{
    m_sides.setTime(time);
    m_dock->updateFrom(m_sides.selectedSettings(), {QStringLiteral("scene.time")});
    pushSettings();
}

void MainWindow::showClock()
{
    const AnimationSettings& clock = m_sides.selectedSettings().animation;
    m_timeline->show(m_clipLength, clock.time, clock.play);
}

void MainWindow::turnLights(double radians)
{
    m_sides.turnLights(radians);
    m_dock->updateFrom(m_sides.selectedSettings(), {QStringLiteral("light.position")});
    pushSettings();
}

QString MainWindow::saveScreenshot(ScreenshotDialog::Target target, const QString& path)
{
    QImage image;
    switch (target) {
    case ScreenshotDialog::Target::SceneView:
        image = m_views[m_sides.selected()]->grabFramebuffer();
        break;
    case ScreenshotDialog::Target::DepthMapView:
        image = m_depthView->grabFramebuffer();
        break;
    case ScreenshotDialog::Target::Window:
        image = grab().toImage();
        break;
    }
    if (const QString error = ScreenshotDialog::write(image, path); !error.isEmpty())
        return error;
    showStatusMessage(tr("Saved %1 (%2×%3)").arg(QDir::toNativeSeparators(path)).arg(image.width()).arg(image.height()), 8000);
    return QString();
}

void MainWindow::saveScreenshotInteractively()
{
    const QString name = screenshotFileName(m_sides.selectedSettings(), QDateTime::currentDateTime());
    ScreenshotDialog dialog(QDir(screenshotFolder()).filePath(name), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_session->setLastFolder(QFileInfo(dialog.path()).absolutePath());
    const QString error = saveScreenshot(dialog.target(), dialog.path());
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Save Screenshot"), error);
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
                          "<p>Renderer: %2</p><p>Built with Qt %3.</p>"
                          "<p>%4. Free software under the %5 licence, with no warranty: you may use, change and redistribute it "
                          "as the LICENSE file that comes with it says.</p>")
                           .arg(QCoreApplication::applicationVersion(), renderer.toHtmlEscaped(), QString::fromLatin1(qVersion()),
                                QString::fromLatin1(kCopyrightLine).toHtmlEscaped(), QString::fromLatin1(kLicenceName)));
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    m_import->cancel();
    m_session->end();
    QMainWindow::closeEvent(event);
}

} // namespace shadowlab
