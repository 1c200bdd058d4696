// The explorer window on the headless platform, driven with QTest input the way a person
// drives it: sliders and fields in the dock, the compare shortcut, clicks on a view. The
// assertions are what that person would check: the picture changed, the two sides match or
// differ, the refused value is marked and the picture stayed, nothing draws while idle.
#include "Application.h"
#include "ArtifactPresets.h"
#include "DepthMapPicture.h"
#include "DepthMapView.h"
#include "ErrorPixels.h"
#include "AccuracyDock.h"
#include "HeadlessTestMain.h"
#include "Loupe.h"
#include "MainWindow.h"
#include "MomentMath.h"
#include "OrbitCamera.h"
#include "PropertiesDock.h"
#include "PropertyFields.h"
#include "Renderer.h"
#include "SceneLibrary.h"
#include "SceneView.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "SettingsSummary.h"
#include "SliderSpinBox.h"
#include "TestPictures.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QUndoStack>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTemporaryDir>

#include <glm/geometric.hpp>

#include <memory>

using namespace shadowlab;

namespace {

const QSize kWindowSize(1000, 560);
using Side = MainWindow::Side;

int frames(const MainWindow& w)
{
    return w.sceneView(Side::A)->frameCount() + w.sceneView(Side::B)->frameCount() + w.depthMapView()->frameCount();
}

// Runs the event loop until every visible view has drawn and then no frame came for 250 ms.
// `s` with front faces in the map, no bias (no footprint offset, the ground in the map) and one
// hard tap: acne everywhere the light grazes.
Settings acneOf(Settings s)
{
    s.bias.cullFront = false;
    s.bias.footprint = false;
    s.bias.skipFloors = false;
    s.bias.slope = 0.0;
    s.bias.min = 0.0;
    s.filter.mode = FilterMode::Hard;
    return s;
}

bool settle(const MainWindow& w)
{
    QElapsedTimer total, quiet;
    total.start();
    quiet.start();
    int last = frames(w);
    while (total.elapsed() < 20000) {
        QTest::qWait(20);
        if (frames(w) != last) {
            last = frames(w);
            quiet.restart();
        }
        const bool drawn = w.sceneView(Side::A)->frameCount() > 0 && w.depthMapView()->frameCount() > 0
            && (!w.compareMode() || w.sceneView(Side::B)->frameCount() > 0);
        if (drawn && quiet.elapsed() > 250)
            return true;
    }
    return false;
}

// Pixels whose colour differs by more than `threshold` in any channel.
int differingPixels(const QImage& a, const QImage& b, int threshold = 8)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int count = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (qAbs(qRed(p) - qRed(q)) > threshold || qAbs(qGreen(p) - qGreen(q)) > threshold || qAbs(qBlue(p) - qBlue(q)) > threshold)
                ++count;
        }
    }
    return count;
}

// Distinct grey levels: a rendered scene or depth map has many, an empty view one.
int distinctLevels(const QImage& image)
{
    QSet<int> levels;
    for (int y = 0; y < image.height(); y += 3) {
        for (int x = 0; x < image.width(); x += 3)
            levels.insert(qGray(image.pixel(x, y)));
    }
    return int(levels.size());
}

} // namespace

class tst_MainWindow : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void opensWithBothViewsRendering();
    void dockSliderChangesTheScene_data();
    void dockSliderChangesTheScene();
    void projectionSwitchChangesTheDepthMap();
    void compareModeShowsTwoSides();
    void saveScreenshotWritesPng_data();
    void saveScreenshotWritesPng();
    void impossibleValueIsShownAtTheFieldAndTheImageStays();
    void viewResizedToZeroAndBack();
    void unwritablePathsAreRefusedAndOldFilesKept_data();
    void unwritablePathsAreRefusedAndOldFilesKept();
    void idleWindowDrawsNoFrames();
    void settingsPersistAcrossWindows();
    void orbitKeepsTheDistanceAndZoomNeverReachesTheTarget();
    void fittedVolumeIsShownReadOnlyAndACutVolumeWarnsAtItsField();
    void spotLightsConeStaysEditableWhenFitted();
    void orbitNeverGoesBelowTheGround_data();
    void orbitNeverGoesBelowTheGround();
    void screenshotNameSaysWhatIsOnScreen();
    void captionsSayWhatTheMapIs_data();
    void captionsSayWhatTheMapIs();
    void compareCaptionsLeadWithWhatDiffers();
    void loupeMagnifiesThePixelsUnderThePointer();
    void wipeShowsBothSidesOverTheSamePixels();
    void frozenFrustumKeepsTheFitWhileTheCameraMoves();
    void objectsCastAndReceiveFromTheDock();
    void accuracyDockOverlaysErrorsAndAppliesSweepPoints();
    void compareModeMeasuresBothSidesWithTheirCost();
    void presetButtonShowsTheArtifactAndTheFix_data();
    void presetButtonShowsTheArtifactAndTheFix();
    void presetFromTheCommandLineShowsItsNoteAndFix();
    void everySettingHasADockField();
    void fieldsTheSettingsIgnoreAreGreyedWithTheReason();
    void cameraFieldsMoveTheSharedCamera();
    void depthLegendSpansTheDepthsInTheMap_data();
    void depthLegendSpansTheDepthsInTheMap();
    void statusBarShowsMediansAndMeasuresFrames();
    void depthPaneFramesTheMapInWhatTheCameraSees_data();
    void depthPaneFramesTheMapInWhatTheCameraSees();
    void timelinePlaysScrubsAndSharesTheClock();
    void onDemandCacheRedrawsWhenAsked();

private:
    SliderSpinBox* field(const QString& key) const { return m_window->propertiesDock()->findChild<SliderSpinBox*>(key); }
    QImage scene(Side side = Side::A) const { return m_window->sceneView(side)->grabFramebuffer(); }
    QImage depthMap() const { return m_window->depthMapView()->grabFramebuffer(); }

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

void tst_MainWindow::initTestCase()
{
    QVERIFY(m_dir.isValid());
    // Never read or write the user's own window state and settings.
    QCoreApplication::setOrganizationName(QStringLiteral("ShadowLabTest"));
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
}

void tst_MainWindow::init()
{
    QSettings().clear();
    m_window = std::make_unique<MainWindow>();
    m_window->resize(kWindowSize);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY(settle(*m_window));
}

void tst_MainWindow::cleanup()
{
    m_window.reset();
}

void tst_MainWindow::opensWithBothViewsRendering()
{
    const QImage sceneImage = scene();
    const QImage depthImage = depthMap();
    QVERIFY(!sceneImage.isNull() && !depthImage.isNull());
    QVERIFY2(distinctLevels(sceneImage) > 20, "the scene view shows a scene, not a cleared buffer");
    QVERIFY2(distinctLevels(depthImage) > 20, "the depth-map view shows the shadow map");
    QVERIFY(m_window->sceneView(Side::A)->renderer()->shadowMap().texture() != 0);
    QCOMPARE(m_window->depthMapView()->source(), m_window->sceneView(Side::A));
    QVERIFY(!m_window->findChild<QLabel*>(QStringLiteral("timingLabel"))->text().isEmpty());
    QVERIFY(m_window->findChild<QLabel*>(QStringLiteral("mapLabel"))->text().contains(QStringLiteral("2048")));
}

void tst_MainWindow::dockSliderChangesTheScene_data()
{
    QTest::addColumn<QString>("setup");     // key=value applied first, so the slider matters
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("key_press");
    QTest::addColumn<int>("presses");
    QTest::addColumn<bool>("depthMapChanges");

    QTest::newRow("light azimuth") << QString() << QStringLiteral("light.azimuth") << int(Qt::Key_PageUp) << 3 << true;
    QTest::newRow("spot light x") << QStringLiteral("light.type=spot") << QStringLiteral("light.position.x") << int(Qt::Key_PageUp) << 3 << true;
    QTest::newRow("bias slope to 0: acne") << QStringLiteral("bias.cull_front=false;bias.footprint=false;bias.skip_floors=false;bias.min=0") << QStringLiteral("bias.slope") << int(Qt::Key_Home) << 1
                                           << false;
    QTest::newRow("pcf kernel to 9") << QStringLiteral("filter.mode=pcf") << QStringLiteral("filter.kernel") << int(Qt::Key_End) << 1
                                     << false;
}

void tst_MainWindow::dockSliderChangesTheScene()
{
    QFETCH(QString, setup);
    QFETCH(QString, key);
    QFETCH(int, key_press);
    QFETCH(int, presses);
    QFETCH(bool, depthMapChanges);

    if (!setup.isEmpty()) {
        Settings settings = m_window->settings(Side::A);
        for (const QString& assignment : setup.split(QLatin1Char(';')))
            applyAssignment(settings, assignment);
        m_window->setSettings(Side::A, settings);
        QVERIFY(settle(*m_window));
    }

    SliderSpinBox* editor = field(key);
    QVERIFY2(editor, qPrintable(key));
    const Settings before = m_window->settings(Side::A);
    const QImage sceneBefore = scene();
    const QImage depthBefore = depthMap();
    const int shadowPasses = m_window->sceneView(Side::A)->renderer()->shadowPassCount();

    editor->slider()->setFocus();
    for (int i = 0; i < presses; ++i)
        QTest::keyClick(editor->slider(), Qt::Key(key_press));
    QVERIFY(settle(*m_window));

    QVERIFY2(m_window->settings(Side::A) != before, "the slider edited the settings");
    const int changed = differingPixels(sceneBefore, scene());
    QVERIFY2(changed > 100, qPrintable(QStringLiteral("%1 pixels of the scene changed").arg(changed)));
    const int depthChanged = differingPixels(depthBefore, depthMap());
    if (depthMapChanges) {
        QVERIFY2(depthChanged > 100, qPrintable(QStringLiteral("%1 pixels of the depth map changed").arg(depthChanged)));
        QVERIFY(m_window->sceneView(Side::A)->renderer()->shadowPassCount() > shadowPasses);
    } else {
        // Lit-pass settings reuse the shadow map.
        QCOMPARE(depthChanged, 0);
        QCOMPARE(m_window->sceneView(Side::A)->renderer()->shadowPassCount(), shadowPasses);
    }
}

void tst_MainWindow::projectionSwitchChangesTheDepthMap()
{
    auto* projection = m_window->propertiesDock()->findChild<QComboBox*>(QStringLiteral("light.projection"));
    QVERIFY(projection);
    const QImage depthBefore = depthMap();
    QVERIFY(field(QStringLiteral("light.extent"))->isVisibleTo(m_window.get()));

    projection->setFocus();
    QTest::keyClick(projection, Qt::Key_Down);
    QVERIFY(settle(*m_window));

    QVERIFY(m_window->settings(Side::A).light.projection == LightProjection::Perspective);
    const int changed = differingPixels(depthBefore, depthMap());
    QVERIFY2(changed > 1000, qPrintable(QStringLiteral("%1 pixels of the depth map changed").arg(changed)));
    // The dock shows what the technique uses: field of view instead of extent.
    QVERIFY(field(QStringLiteral("light.fov"))->isVisibleTo(m_window.get()));
    QVERIFY(!field(QStringLiteral("light.extent"))->isVisibleTo(m_window.get()));
}

void tst_MainWindow::compareModeShowsTwoSides()
{
    SceneView* a = m_window->sceneView(Side::A);
    SceneView* b = m_window->sceneView(Side::B);
    QVERIFY(!b->isVisible());

    QTest::keyClick(m_window.get(), Qt::Key_D, Qt::ControlModifier);
    QVERIFY(m_window->compareMode());
    QVERIFY(settle(*m_window));
    QVERIFY(a->isVisible() && b->isVisible());
    // An odd width cannot split evenly; one pixel more for the window makes it even.
    for (int tries = 0; tries < 3 && a->size() != b->size(); ++tries) {
        m_window->resize(m_window->width() + 1, m_window->height());
        QVERIFY(settle(*m_window));
    }
    QCOMPARE(a->size(), b->size());

    // Equal settings, same camera, same size: the same pixels.
    QCOMPARE(m_window->settings(Side::A), m_window->settings(Side::B));
    QCOMPARE(differingPixels(scene(Side::A), scene(Side::B), 2), 0);

    // Select B by clicking it; the dock and the depth map follow it.
    QTest::mouseClick(b, Qt::LeftButton, {}, QPoint(b->width() / 2, b->height() / 2));
    QCOMPARE(m_window->selectedSide(), Side::B);
    QCOMPARE(m_window->depthMapView()->source(), b);
    auto* shadows = m_window->propertiesDock()->findChild<QCheckBox*>(QStringLiteral("shadow.enabled"));
    QTest::mouseClick(shadows, Qt::LeftButton, {}, QPoint(8, shadows->height() / 2));
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::B).shadow.enabled, false);
    QCOMPARE(m_window->settings(Side::A).shadow.enabled, true);
    const int differ = differingPixels(scene(Side::A), scene(Side::B));
    QVERIFY2(differ > 100, qPrintable(QStringLiteral("A and B differ in %1 pixels").arg(differ)));

    // A camera move in one view moves both.
    QTest::mousePress(a, Qt::LeftButton, {}, QPoint(100, 100));
    QTest::mouseMove(a, QPoint(140, 110));
    QTest::mouseRelease(a, Qt::LeftButton, {}, QPoint(140, 110));
    QVERIFY(m_window->settings(Side::A).camera != presetSettings(QStringLiteral("seed")).camera);
    QCOMPARE(m_window->settings(Side::A).camera, m_window->settings(Side::B).camera);
    QCOMPARE(m_window->selectedSide(), Side::A);    // pressing in a view selects its side
    QVERIFY(shadows->isChecked());

    m_window->action(QStringLiteral("swapAction"))->trigger();
    QCOMPARE(m_window->settings(Side::A).shadow.enabled, false);
    QVERIFY(!shadows->isChecked());     // the dock edits A, which now has B's settings

    m_window->action(QStringLiteral("copyAction"))->trigger();
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A), m_window->settings(Side::B));
    QCOMPARE(differingPixels(scene(Side::A), scene(Side::B), 2), 0);
}

void tst_MainWindow::saveScreenshotWritesPng_data()
{
    QTest::addColumn<int>("target");
    QTest::newRow("scene view") << int(ScreenshotDialog::Target::SceneView);
    QTest::newRow("depth-map view") << int(ScreenshotDialog::Target::DepthMapView);
    QTest::newRow("whole window") << int(ScreenshotDialog::Target::Window);
}

void tst_MainWindow::saveScreenshotWritesPng()
{
    QFETCH(int, target);
    const auto which = ScreenshotDialog::Target(target);
    const QString path = m_dir.filePath(QStringLiteral("shot-%1.png").arg(target));
    QSize expected;
    switch (which) {
    case ScreenshotDialog::Target::SceneView: expected = m_window->sceneView(Side::A)->size(); break;
    case ScreenshotDialog::Target::DepthMapView: expected = m_window->depthMapView()->size(); break;
    case ScreenshotDialog::Target::Window: expected = m_window->size(); break;
    }

    // The real action and dialog; only the typing in the dialog is done by code.
    QString defaultPath;
    QTimer::singleShot(0, this, [&] {
        auto* dialog = qobject_cast<ScreenshotDialog*>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        defaultPath = dialog->path();
        dialog->setTarget(which);
        dialog->setPath(path);
        dialog->accept();
    });
    m_window->action(QStringLiteral("screenshotAction"))->trigger();

    QVERIFY2(QFileInfo(defaultPath).fileName().startsWith(QStringLiteral("shadowlab-")), qPrintable(defaultPath));
    QVERIFY2(defaultPath.contains(QStringLiteral("-seed-")) && defaultPath.endsWith(QStringLiteral("-2048.png")), qPrintable(defaultPath));
    QImage image;
    QVERIFY2(image.load(path, "PNG"), qPrintable(path));
    QCOMPARE(image.size(), expected * m_window->devicePixelRatio());
    QVERIFY(distinctLevels(image) > 20);
}

void tst_MainWindow::impossibleValueIsShownAtTheFieldAndTheImageStays()
{
    PropertiesDock* dock = m_window->propertiesDock();
    Settings manual = m_window->settings(Side::A);
    manual.light.fit = LightFit::Manual;      // near and far are the user's only then
    m_window->setSettings(Side::A, manual);
    QVERIFY(settle(*m_window));
    SliderSpinBox* nearField = field(QStringLiteral("light.near"));
    const QImage before = scene();
    const QImage depthBefore = depthMap();

    // near 9 >= far 7.5: typed into the spin box and confirmed with Enter.
    QDoubleSpinBox* spin = nearField->spinBox();
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("9"));
    QTest::keyClick(spin, Qt::Key_Enter);
    QVERIFY(settle(*m_window));

    QCOMPARE(spin->value(), 9.0);                                  // the field keeps what was typed
    QCOMPARE(m_window->settings(Side::A).light.nearPlane, 1.0);    // the window does not take it
    QVERIFY(nearField->isInvalid());
    QVERIFY2(dock->errorText(QStringLiteral("light.far")).contains(QStringLiteral("greater than near")),
             qPrintable(dock->errorText(QStringLiteral("light.far"))));
    QVERIFY(!dock->errorText(QStringLiteral("light.near")).isEmpty());
    QCOMPARE(differingPixels(before, scene(), 0), 0);
    QCOMPARE(differingPixels(depthBefore, depthMap(), 0), 0);

    // Correcting it clears the marks and applies.
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("2"));
    QTest::keyClick(spin, Qt::Key_Enter);
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A).light.nearPlane, 2.0);
    QVERIFY(!nearField->isInvalid());
    QVERIFY(dock->errorText(QStringLiteral("light.far")).isEmpty());
}

void tst_MainWindow::viewResizedToZeroAndBack()
{
    auto* splitter = m_window->findChild<QSplitter*>(QStringLiteral("mainSplitter"));
    const QList<int> sizes = splitter->sizes();
    splitter->setSizes({0, sizes[0] + sizes[1]});
    QVERIFY(settle(*m_window));
    // A view squeezed to nothing would never draw again: it keeps its minimum instead.
    QVERIFY(m_window->sceneView(Side::A)->minimumWidth() > 0);
    QCOMPARE(m_window->sceneView(Side::A)->width(), m_window->sceneView(Side::A)->minimumWidth());
    splitter->setSizes({sizes[0] + sizes[1], 0});
    QVERIFY(settle(*m_window));

    m_window->resize(120, 90);
    QVERIFY(settle(*m_window));
    m_window->resize(kWindowSize);
    splitter->setSizes(sizes);
    QVERIFY(settle(*m_window));
    QVERIFY(distinctLevels(scene()) > 20);
    QVERIFY(distinctLevels(depthMap()) > 20);
}

void tst_MainWindow::unwritablePathsAreRefusedAndOldFilesKept_data()
{
    QTest::addColumn<QString>("what");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("mentions");
    for (const char* what : {"export", "screenshot"}) {
        QTest::addRow("%s to /dev/full", what) << what << "/dev/full" << "not a file";
        QTest::addRow("%s into /proc", what) << what << "/proc/nope.json" << "does not accept new files";
        QTest::addRow("%s into a missing folder", what) << what << "%DIR%/missing/x.json" << "does not exist";
        QTest::addRow("%s over a folder", what) << what << "%DIR%" << "folder";
    }
}

void tst_MainWindow::unwritablePathsAreRefusedAndOldFilesKept()
{
    QFETCH(QString, what);
    QFETCH(QString, path);
    QFETCH(QString, mentions);
    const QString folder = m_dir.filePath(QStringLiteral("unwritable-") + what);
    QVERIFY(QDir().mkpath(folder));
    const QString old = folder + QStringLiteral("/old.json");
    const QByteArray oldContent("{\"bias.slope\": 0.25}");
    {
        QFile f(old);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(oldContent) == oldContent.size());
    }
    path.replace(QStringLiteral("%DIR%"), folder);
    const QString error = what == u"export" ? m_window->exportSettings(path)
                                            : m_window->saveScreenshot(ScreenshotDialog::Target::SceneView, path);
    QVERIFY2(error.contains(mentions), qPrintable(error));
    QStringList left = QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    QCOMPARE(left, QStringList{QStringLiteral("old.json")}); // nothing partial or temporary

    // Over an existing file the write replaces it whole.
    QVERIFY2((what == u"export" ? m_window->exportSettings(old) : m_window->saveScreenshot(ScreenshotDialog::Target::SceneView, old)).isEmpty(),
             "writing over an existing file failed");
    QFile written(old);
    QVERIFY(written.open(QIODevice::ReadOnly));
    const QByteArray bytes = written.readAll();
    if (what == u"export")
        QCOMPARE(loadSettingsFile(old, Settings{}).bias.slope, m_window->settings(Side::A).bias.slope);
    else
        QVERIFY(!QImage::fromData(bytes, "PNG").isNull());
    left = QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    QCOMPARE(left, QStringList{QStringLiteral("old.json")});
}

void tst_MainWindow::idleWindowDrawsNoFrames()
{
    const int sceneFrames = m_window->sceneView(Side::A)->frameCount();
    const int depthFrames = m_window->depthMapView()->frameCount();
    QTest::qWait(300);
    QCOMPARE(m_window->sceneView(Side::A)->frameCount(), sceneFrames);
    QCOMPARE(m_window->depthMapView()->frameCount(), depthFrames);

    // While the light animates it draws; when it stops, it stops drawing.
    m_window->setLightAnimation(true, 90.0);
    QTRY_VERIFY(m_window->sceneView(Side::A)->frameCount() >= sceneFrames + 3);
    QVERIFY(m_window->depthMapView()->frameCount() > depthFrames);
    m_window->setLightAnimation(false, 90.0);
    QVERIFY(settle(*m_window));
    const int stopped = m_window->sceneView(Side::A)->frameCount();
    QTest::qWait(300);
    QCOMPARE(m_window->sceneView(Side::A)->frameCount(), stopped);
}

void tst_MainWindow::settingsPersistAcrossWindows()
{
    SliderSpinBox* slope = field(QStringLiteral("bias.slope"));
    slope->spinBox()->setValue(0.05);
    QCOMPARE(m_window->settings(Side::A).bias.slope, 0.05);
    m_window->close();
    m_window.reset();

    MainWindow again;
    QCOMPARE(again.settings(Side::A).bias.slope, 0.05);
    QCOMPARE(again.propertiesDock()->findChild<SliderSpinBox*>(QStringLiteral("bias.slope"))->value(), 0.05);

    MainWindow fresh(MainWindow::Persistence::None);
    QCOMPARE(fresh.settings(Side::A), presetSettings(QStringLiteral("seed")));
}

void tst_MainWindow::orbitKeepsTheDistanceAndZoomNeverReachesTheTarget()
{
    const CameraSettings start = presetSettings(QStringLiteral("torus")).camera;
    OrbitCamera camera(start);
    camera.orbit(45.0, 200.0);  // far past the pole: pitch stops short of it
    const glm::dvec3 offset = camera.settings().position - camera.settings().target;
    QVERIFY(qAbs(glm::length(offset) - glm::length(start.position - start.target)) < 1e-9);
    QVERIFY(offset.y / glm::length(offset) < 1.0 - 1e-6);

    camera.zoom(1000.0);
    QVERIFY(glm::length(camera.settings().position - camera.settings().target) > 0.0);
    Settings settings = presetSettings(QStringLiteral("torus"));
    settings.camera = camera.settings();
    QVERIFY(validate(settings).empty());

    OrbitCamera panned(start);
    panned.pan(QPointF(100.0, 0.0), QSize(800, 600));
    QVERIFY(glm::length((panned.settings().position - start.position) - (panned.settings().target - start.target)) < 1e-9);
}

// light.fit=scene: the volume's fields are read-only and show the fitted numbers; a manual
// volume that cuts what the camera sees says so at the field and in the status bar.
void tst_MainWindow::fittedVolumeIsShownReadOnlyAndACutVolumeWarnsAtItsField()
{
    PropertiesDock* dock = m_window->propertiesDock();
    Settings s = presetSettings(QStringLiteral("seed"));
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    SliderSpinBox* extent = field(QStringLiteral("light.extent"));
    SliderSpinBox* farField = field(QStringLiteral("light.far"));
    QVERIFY(!extent->isEnabled() && !farField->isEnabled());
    const LightVolume& v = m_window->sceneView(Side::A)->renderer()->lastFit().volume;
    QCOMPARE_LT(std::abs(extent->value() - 0.5 * std::max(v.width(), v.height())), 0.01);
    QCOMPARE_LT(extent->value(), s.light.extent);     // the fitted extent, not the 10 as set
    QVERIFY(dock->warningText(QStringLiteral("light.far")).isEmpty());

    s.light.fit = LightFit::Manual;
    s.light.farPlane = 4.0;
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    QVERIFY(extent->isEnabled() && farField->isEnabled());
    QCOMPARE(farField->value(), 4.0);
    const QString hint = dock->warningText(QStringLiteral("light.extent")) + dock->warningText(QStringLiteral("light.near"))
                       + dock->warningText(QStringLiteral("light.far"));
    QVERIFY2(hint.contains(QStringLiteral("lit without a shadow test")), qPrintable(hint));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("outside the light volume")),
             qPrintable(m_window->statusMessage()));

    m_window->setSettings(Side::A, presetSettings(QStringLiteral("seed")));
    QVERIFY(settle(*m_window));
    QVERIFY(dock->warningText(QStringLiteral("light.extent")).isEmpty() && dock->warningText(QStringLiteral("light.far")).isEmpty());
}

void tst_MainWindow::spotLightsConeStaysEditableWhenFitted()
{
    // A spot light's field of view is its cone: fitting shapes the map inside it, and says so,
    // but the cone stays the user's; near and far are fitted as for any light.
    PropertiesDock* dock = m_window->propertiesDock();
    Settings s = presetSettings(QStringLiteral("seed"));
    applySetting(s, QStringLiteral("light.type"), QStringLiteral("spot"));
    s.light.fov = 100.0;
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    SliderSpinBox* fov = field(QStringLiteral("light.fov"));
    QVERIFY(fov->isEnabled());
    QVERIFY(!field(QStringLiteral("light.far"))->isEnabled());
    QCOMPARE(fov->value(), 100.0);
    const QString note = dock->warningText(QStringLiteral("light.fov"));
    const auto spans = [](const QString& text) {
        const int at = text.indexOf(QStringLiteral("spans "));
        return at < 0 ? qQNaN() : QStringView(text).mid(at + 6).toString().section(QChar(0xB0), 0, 0).toDouble();
    };
    const double fitted = spans(note);
    // (Stabilised maps round their size up, so the map may be a little wider than the cone.)
    QVERIFY2(fitted > 0.0 && fitted < 120.0, qPrintable(note));

    // Narrowing the cone from the dock is a change of the light, and the map follows it.
    fov->setValue(60.0);
    emit fov->valueEdited(60.0);
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A).light.fov, 60.0);
    QCOMPARE(fov->value(), 60.0);
    const QString narrower = dock->warningText(QStringLiteral("light.fov"));
    const double refitted = spans(narrower);
    QVERIFY2(refitted > 0.0 && refitted < fitted, qPrintable(note + QStringLiteral(" / ") + narrower));

    // A point light's faces are fitted whole: nothing there for the user to set.
    applySetting(s, QStringLiteral("light.type"), QStringLiteral("point"));
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    QVERIFY(!fov->isEnabled());
}

void tst_MainWindow::orbitNeverGoesBelowTheGround_data()
{
    QTest::addColumn<QString>("scene");
    for (const QString& name : sceneNames())
        QTest::newRow(qPrintable(name)) << name;
}

// Dragging down as far as one likes, zooming out and panning down: the camera stays above the
// preset's ground plane, and keeps its distance while orbiting.
void tst_MainWindow::orbitNeverGoesBelowTheGround()
{
    QFETCH(QString, scene);
    const Scene built = buildScene(scene);
    QVERIFY(built.groundHeight.has_value());
    const double ground = *built.groundHeight;
    const CameraSettings start = presetSettings(scene).camera;
    const double distance = glm::length(start.position - start.target);
    OrbitCamera camera(start, ground);
    for (int i = 0; i < 40; ++i) {
        camera.orbit(7.0, -11.0);
        QCOMPARE_GT(camera.settings().position.y, ground);
        QVERIFY(qAbs(glm::length(camera.settings().position - camera.settings().target) - distance) < 1e-9 * distance);
    }
    camera.zoom(-20.0);
    QCOMPARE_GT(camera.settings().position.y, ground);
    for (int i = 0; i < 40; ++i)
        camera.pan(QPointF(0.0, -200.0), QSize(800, 600));
    QCOMPARE_GT(camera.settings().position.y, ground);
    // Without a ground, the same drag goes under.
    OrbitCamera free(start);
    for (int i = 0; i < 40; ++i)
        free.orbit(7.0, -11.0);
    QCOMPARE_LT(free.settings().position.y, ground);
}

void tst_MainWindow::screenshotNameSaysWhatIsOnScreen()
{
    Settings settings = presetSettings(QStringLiteral("cubes"));
    settings.filter.mode = FilterMode::Pcf;
    settings.filter.kernel = 5;
    settings.map.size = 1024;
    const QDateTime when(QDate(2026, 11, 22), QTime(15, 30));
    QCOMPARE(screenshotFileName(settings, when), QStringLiteral("shadowlab-2026-11-22-1530-cubes-pcf5-1024.png"));
    settings.filter.mode = FilterMode::HwBilinear;
    QCOMPARE(screenshotFileName(settings, when), QStringLiteral("shadowlab-2026-11-22-1530-cubes-hw-bilinear-1024.png"));
}

void tst_MainWindow::captionsSayWhatTheMapIs_data()
{
    QTest::addColumn<QStringList>("assignments");
    QTest::addColumn<QString>("depthPane");     // what the depth pane's caption must say
    QTest::addColumn<QString>("scenePane");     // ... and the scene pane's
    QTest::newRow("ortho map") << QStringList{} << QStringLiteral("ortho light, depth24") << QStringLiteral("2048² ortho");
    QTest::newRow("spot") << QStringList{QStringLiteral("light.type=spot"), QStringLiteral("light.projection=perspective"),
                                         QStringLiteral("map.size=1024")}
                          << QStringLiteral("perspective light, depth24") << QStringLiteral("1024² perspective");
    QTest::newRow("point") << QStringList{QStringLiteral("light.type=point"), QStringLiteral("light.projection=perspective"),
                                          QStringLiteral("map.size=512")}
                           << QStringLiteral("point light, six cube faces of 512², depth24") << QStringLiteral("six 512² cube faces");
    QTest::newRow("cascades") << QStringList{QStringLiteral("shadow.cascades=4"), QStringLiteral("map.format=depth32f")}
                              << QStringLiteral("4 cascades of 2048², depth32f") << QStringLiteral("4 cascades of 2048²");
    QTest::newRow("virtual") << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.virtual_pool=16")}
                             << QStringLiteral("virtual map, a pool of 256 pages of 128² (2176² depth24)")
                             << QStringLiteral("virtual map of 256 pages of 128²");
    QTest::newRow("moments") << QStringList{QStringLiteral("filter.mode=msm")} << QStringLiteral("ortho light, moments RGBA32F")
                             << QStringLiteral("2048² ortho");
}

// Side A with a hand-set volume and side B with a fitted one read alike in the summary
// ("hw-bilinear · slope 0.01 · …"): in compare mode each caption leads with where it differs.
void tst_MainWindow::compareCaptionsLeadWithWhatDiffers()
{
    const Settings a = m_window->settings(Side::A);
    Settings b = a;
    applySetting(b, "light.fit", "manual");
    QVERIFY(comparedSummary(b, a).startsWith("light.fit manual — "));
    QVERIFY(comparedSummary(a, b).startsWith("light.fit scene — "));
    QVERIFY(comparedSummary(a, a).startsWith("the same settings"));
    applySetting(b, "map.size", "512");
    applySetting(b, "filter.mode", "pcf");
    applySetting(b, "bias.normal", "1");
    applySetting(b, "shadow.enabled", "true");
    QVERIFY2(comparedSummary(b, a).contains(" · 1 more — "), qPrintable(comparedSummary(b, a)));

    m_window->setCompareMode(true);
    m_window->setSettings(Side::B, b);
    const auto captionOf = [&](const QString& start) {
        for (QLabel* label : m_window->findChildren<QLabel*>()) {
            if (label->toolTip().startsWith(start))
                return true;
        }
        return false;
    };
    QVERIFY(captionOf("light.fit manual · map.size 512"));
    QVERIFY(captionOf("light.fit scene · map.size 2048"));
    m_window->setCompareMode(false);
}

// View > Loupe: the pixels under the pointer, magnified beside it from the last frame; moving
// the pointer redraws the loupe, not the scene.
void tst_MainWindow::loupeMagnifiesThePixelsUnderThePointer()
{
    SceneView* view = m_window->sceneView(Side::A);
    m_window->action(QStringLiteral("loupeAction"))->trigger();
    QVERIFY(view->loupe());
    QTRY_VERIFY(!view->loupeFrame().isNull());
    QVERIFY(settle(*m_window));
    auto* loupe = view->findChild<Loupe*>(QStringLiteral("loupe"));
    QVERIFY(loupe);
    const int frames = view->frameCount();
    for (const QPoint at : {QPoint(view->width() / 2, view->height() / 2), QPoint(view->width() - 5, view->height() - 5), QPoint(40, 30)}) {
        // A plain move with no button held, as the pointer passes over the view.
        QMouseEvent move(QEvent::MouseMove, QPointF(at), view->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(view, &move);
        QVERIFY(loupe->isVisible());
        QVERIFY2(view->rect().contains(loupe->geometry()), qPrintable(QStringLiteral("%1,%2 %3x%4 in %5x%6").arg(loupe->x()).arg(loupe->y()).arg(loupe->width()).arg(loupe->height()).arg(view->width()).arg(view->height())));      // beside the pointer, inside the view
        const QPoint centre = loupe->centre();
        const QImage shown = loupe->grab().toImage();
        const int middle = 1 + Loupe::kRadius * Loupe::kZoom + Loupe::kZoom / 2;
        QCOMPARE(QColor(shown.pixel(middle * shown.devicePixelRatio(), middle * shown.devicePixelRatio())).rgb(),
                 QColor(view->loupeFrame().pixel(centre)).rgb());
    }
    QCOMPARE(view->frameCount(), frames);
    keepPicture(m_window.get(), QStringLiteral("loupe"));
    m_window->action(QStringLiteral("loupeAction"))->trigger();
    QVERIFY(!view->loupe() && view->loupeFrame().isNull());
}

// View > Wipe A | B: one view, side A left of a divider and side B right of it over the same
// pixels; dragging the divider moves it (not the camera); a click on B's part selects B.
void tst_MainWindow::wipeShowsBothSidesOverTheSamePixels()
{
    SceneView* view = m_window->sceneView(Side::A);
    m_window->setCompareMode(true);
    Settings b = m_window->settings(Side::A);
    applySetting(b, "shading.shadow_only", "true");     // B's pixels unlike A's everywhere
    m_window->setSettings(Side::B, b);
    m_window->action(QStringLiteral("wipeAction"))->trigger();
    QVERIFY(m_window->wiping() && view->wiping());
    QVERIFY(!m_window->sceneView(Side::B)->isVisible());
    QVERIFY(settle(*m_window));
    keepPicture(m_window.get(), QStringLiteral("wipe"));
    const QImage wiped = view->grabFramebuffer();
    Settings a = m_window->settings(Side::A);
    m_window->setWipe(false);
    m_window->setCompareMode(false);
    QVERIFY(settle(*m_window));
    // A alone at the wiped view's size: the left of the wipe is A's, the right is not.
    view->resize(wiped.deviceIndependentSize().toSize());
    const QImage alone = view->grabFramebuffer();
    QCOMPARE(alone.size(), wiped.size());
    const int divider = wiped.width() / 2;
    int leftDiffers = 0, rightDiffers = 0;
    for (int y = 40; y < wiped.height(); y += 3) {       // below the side labels
        for (int x = 0; x < wiped.width(); x += 3) {
            if (std::abs(x - divider) <= 12)
                continue;                                // the divider and its handle
            const bool differs = wiped.pixel(x, y) != alone.pixel(x, y);
            (x < divider ? leftDiffers : rightDiffers) += differs;
        }
    }
    QVERIFY2(leftDiffers == 0 && rightDiffers > 100, qPrintable(QStringLiteral("left %1, right %2").arg(leftDiffers).arg(rightDiffers)));

    // The divider drags, the camera stays; a click right of it selects side B.
    m_window->setCompareMode(true);
    m_window->setWipe(true);
    QVERIFY(settle(*m_window));
    const CameraSettings camera = m_window->settings(Side::A).camera;
    const QPoint on(int(view->wipePosition() * view->width()), view->height() / 3);
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, on);
    QMouseEvent move(QEvent::MouseMove, QPointF(view->width() / 4, on.y()), view->mapToGlobal(QPointF(view->width() / 4, on.y())),
                     Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, QPoint(view->width() / 4, on.y()));
    QVERIFY2(std::abs(view->wipePosition() - 0.25) < 0.02, qPrintable(QString::number(view->wipePosition())));
    QVERIFY(m_window->settings(Side::A).camera == camera);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, QPoint(view->width() * 3 / 4, view->height() / 3));
    QCOMPARE(m_window->selectedSide(), Side::B);
    m_window->setCompareMode(false);
    QVERIFY(!m_window->wiping() && !view->wiping());
    QVERIFY(a == m_window->settings(Side::A));
}

// View > Freeze Shadow Frustum: the light stays fitted to the camera of that moment while the
// camera moves away to look at the fit from outside; unfrozen, it follows the camera again.
void tst_MainWindow::frozenFrustumKeepsTheFitWhileTheCameraMoves()
{
    Settings s = presetSettings(QStringLiteral("city"));
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    SceneView* view = m_window->sceneView(Side::A);
    const glm::dmat4 fitted = view->renderer()->lightFrame().viewProjection;
    m_window->action(QStringLiteral("freezeAction"))->trigger();
    QVERIFY(view->frozenCamera().has_value());
    keepPicture(m_window.get(), QStringLiteral("frozen-before"));
    // Back and up, looking down at the street the fit was made for.
    CameraSettings away = s.camera;
    away.position = s.camera.target + (s.camera.position - s.camera.target) * 4.0 + glm::dvec3(0.0, 60.0, 0.0);
    s.camera = away;
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    keepPicture(m_window.get(), QStringLiteral("frozen-away"));
    QVERIFY(view->renderer()->lightFrame().viewProjection == fitted);
    m_window->action(QStringLiteral("freezeAction"))->trigger();
    QVERIFY(!view->frozenCamera());
    QVERIFY(settle(*m_window));
    QVERIFY(view->renderer()->lightFrame().viewProjection != fitted);     // fitted to the camera now
}

// The scene's objects listed in the dock: unchecking one in "Casts a shadow" takes its shadow
// away, as one undo step; "Receives shadows" keeps an object lit.
void tst_MainWindow::objectsCastAndReceiveFromTheDock()
{
    m_window->setSettings(Side::A, presetSettings(QStringLiteral("seed")));
    QVERIFY(settle(*m_window));
    auto* casts = m_window->propertiesDock()->findChild<QListWidget*>(QStringLiteral("objects.no_cast"));
    auto* receives = m_window->propertiesDock()->findChild<QListWidget*>(QStringLiteral("objects.no_receive"));
    QVERIFY(casts && receives);
    QTRY_COMPARE(casts->count(), 4);
    const QList<QListWidgetItem*> high = casts->findItems(QStringLiteral("high cube"), Qt::MatchExactly);
    QCOMPARE(high.size(), 1);
    QCOMPARE(high.front()->checkState(), Qt::Checked);
    const QImage before = m_window->sceneView(Side::A)->grabFramebuffer();
    const int steps = m_window->undoStack(Side::A)->count();
    high.front()->setCheckState(Qt::Unchecked);
    QCOMPARE(m_window->settings(Side::A).objects.noCast, QStringList{QStringLiteral("high cube")});
    QCOMPARE(m_window->undoStack(Side::A)->count(), steps + 1);
    QVERIFY(settle(*m_window));
    QVERIFY(m_window->sceneView(Side::A)->grabFramebuffer() != before);
    receives->findItems(QStringLiteral("ground"), Qt::MatchExactly).front()->setCheckState(Qt::Unchecked);
    QCOMPARE(m_window->settings(Side::A).objects.noReceive, QStringList{QStringLiteral("ground")});
    m_window->undoStack(Side::A)->undo();
    m_window->undoStack(Side::A)->undo();
    QVERIFY(m_window->settings(Side::A).objects.noCast.isEmpty());
    QCOMPARE(casts->findItems(QStringLiteral("high cube"), Qt::MatchExactly).front()->checkState(), Qt::Checked);
}

// A new user read "ortho light" over a virtual map's pool: each caption names the map it shows,
// and the window's depth pane carries the same words.
void tst_MainWindow::captionsSayWhatTheMapIs()
{
    QFETCH(QStringList, assignments);
    QFETCH(QString, depthPane);
    QFETCH(QString, scenePane);
    Settings settings = m_window->settings(Side::A);
    for (const QString& a : assignments)
        applyAssignment(settings, a);
    ensureValid(settings);
    QCOMPARE(shadowMapSummary(settings), depthPane);
    QVERIFY2(settingsSummary(settings).contains(QStringLiteral(" · ") + scenePane), qPrintable(settingsSummary(settings)));
    // A moments map draws every face: its caption does not say front faces are culled.
    QVERIFY2(settingsSummary(settings).contains(QStringLiteral("front faces culled")) == (settings.bias.cullFront && !isMomentTechnique(settings.filter.mode)),
             qPrintable(settingsSummary(settings)));
    m_window->setSettings(Side::A, settings);
    QVERIFY(settle(*m_window));
    bool shown = false;
    for (const QLabel* label : m_window->findChildren<QLabel*>())
        shown = shown || label->toolTip() == depthPane;
    QVERIFY2(shown, qPrintable(depthPane));
    // The picture's own label says how several views lie: a point light's six faces in a 3 × 2
    // grid, four cascades in a 2 × 2 one (not "side by side").
    const DepthMapFacts facts = depthMapFacts(*m_window->sceneView(Side::A)->renderer(), std::nullopt);
    if (settings.light.type == LightType::Point)
        QVERIFY2(volumeTexts(facts).front().startsWith("6 views in a 3 × 2 grid"), qPrintable(volumeTexts(facts).front()));
    else if (settings.shadow.cascades == 4)
        QVERIFY2(volumeTexts(facts).front().startsWith("4 views in a 2 × 2 grid"), qPrintable(volumeTexts(facts).front()));
}

void tst_MainWindow::accuracyDockOverlaysErrorsAndAppliesSweepPoints()
{
    AccuracyDock* dock = m_window->accuracyDock();
    QVERIFY(dock);
    dock->setAreaSamplesPerAxis(2);
    const Settings acne = acneOf(m_window->settings(Side::A));
    m_window->setSettings(Side::A, acne);
    QVERIFY(settle(*m_window));
    const QImage before = scene();

    dock->findChild<QCheckBox*>(QStringLiteral("overlayCheck"))->setChecked(true);
    QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("compareButton")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dock->isBusy() && !m_window->sceneView(Side::A)->errorOverlay().isNull(), 60000);
    QVERIFY(settle(*m_window));
    // The acne shows as false shadow (magenta) over the greyed scene.
    const QImage overlaid = scene();
    const int magenta = falseShadowPixels(overlaid, 2);
    QVERIFY2(magenta > 200, qPrintable(QString::number(magenta)));
    QVERIFY(overlaid != before);

    // Any edit makes the measurement stale: the overlay goes.
    Settings fixed = acne;
    fixed.bias.min = 0.001;
    m_window->setSettings(Side::A, fixed);
    QVERIFY(m_window->sceneView(Side::A)->errorOverlay().isNull());

    // A sweep point applied from the dock becomes the selected side's settings.
    QSignalSpy applied(dock, &AccuracyDock::applySettingsRequested);
    Settings chosen = fixed;
    chosen.filter.mode = FilterMode::Pcf64;
    emit dock->applySettingsRequested(chosen);
    QCOMPARE(applied.count(), 1);
    QVERIFY(m_window->settings(Side::A).filter.mode == FilterMode::Pcf64);
}

void tst_MainWindow::compareModeMeasuresBothSidesWithTheirCost()
{
    // A clean A beside an acned B: one click measures both, each view gets its own errors, and
    // the dock holds both sides' error and frame time with the difference.
    AccuracyDock* dock = m_window->accuracyDock();
    dock->setAreaSamplesPerAxis(2);
    m_window->setCompareMode(true);
    const Settings acne = acneOf(m_window->settings(Side::A));
    m_window->setSettings(Side::B, acne);
    m_window->selectSide(Side::A);
    QVERIFY(settle(*m_window));
    QCOMPARE(dock->windowTitle(), QStringLiteral("Accuracy — A and B"));
    const auto text = [dock](const char* name) { return dock->findChild<QLabel*>(QLatin1String(name))->text(); };
    // Frame times of both sides, from the views' own frames.
    QTRY_VERIFY(text("frameTimeValue").endsWith(QStringLiteral(" ms")) && text("frameTimeValueB").endsWith(QStringLiteral(" ms")));
    QVERIFY2(!text("frameTimeDelta").isEmpty() && text("frameTimeDelta") != QStringLiteral("—"), qPrintable(text("frameTimeDelta")));

    dock->findChild<QCheckBox*>(QStringLiteral("overlayCheck"))->setChecked(true);
    QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("compareButton")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!dock->isBusy() && !m_window->sceneView(Side::A)->errorOverlay().isNull()
                                 && !m_window->sceneView(Side::B)->errorOverlay().isNull(),
                             60000);
    const auto falseShadow = [](const QImage& errors) { return falseShadowPixels(errors); };
    const int a = falseShadow(m_window->sceneView(Side::A)->errorOverlay());
    const int b = falseShadow(m_window->sceneView(Side::B)->errorOverlay());
    QVERIFY2(b > 10 * (a + 1), qPrintable(QStringLiteral("false-shadow pixels: A %1, B %2").arg(a).arg(b)));
    QVERIFY2(text("misclassifiedDelta").startsWith(QLatin1Char('+')), qPrintable(text("misclassifiedDelta")));
    keepPicture(m_window.get(), QStringLiteral("compare-errors"));
    // The heat map of |V - V_ref| in their place, over both views.
    auto* kind = dock->findChild<QComboBox*>(QStringLiteral("overlayKind"));
    kind->setCurrentIndex(1);
    QVERIFY(settle(*m_window));
    keepPicture(m_window.get(), QStringLiteral("compare-heat"));
    kind->setCurrentIndex(0);
    // The window's screenshot shows B's errors too (a grab redirects widget painters).
    QVERIFY(settle(*m_window));
    SceneView* viewB = m_window->sceneView(Side::B);
    const QImage shot = m_window->grab(QRect(viewB->mapTo(m_window.get(), QPoint(0, 0)), viewB->size())).toImage();
    QVERIFY2(falseShadow(shot) > falseShadow(m_window->sceneView(Side::B)->errorOverlay()) / 4,
             qPrintable(QStringLiteral("%1 magenta pixels in the screenshot of B").arg(falseShadow(shot))));

    // Editing B keeps A's overlay; B's goes, as its measurement is stale.
    m_window->selectSide(Side::B);
    Settings fixed = acne;
    fixed.bias.min = 0.002;
    m_window->setSettings(Side::B, fixed);
    QVERIFY(!m_window->sceneView(Side::A)->errorOverlay().isNull());
    QVERIFY(m_window->sceneView(Side::B)->errorOverlay().isNull());

    // The three columns fit the dock at the default window size: no sideways scrolling.
    m_window->resize(1200, 750);
    dock->raise();
    QVERIFY(settle(*m_window));
    QTest::qWait(50);
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    QVERIFY(scroll);
    QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
             qPrintable(QStringLiteral("content %1 px in %2").arg(scroll->widget()->minimumSizeHint().width()).arg(scroll->viewport()->width())));

    // Leaving compare mode hides B's column and its overlay.
    m_window->setCompareMode(false);
    QVERIFY(!dock->findChild<QLabel*>(QStringLiteral("misclassifiedValueB"))->isVisibleTo(dock));
    QVERIFY(m_window->sceneView(Side::B)->errorOverlay().isNull());
    QCOMPARE(dock->windowTitle(), QStringLiteral("Accuracy"));
}

void tst_MainWindow::presetButtonShowsTheArtifactAndTheFix_data()
{
    QTest::addColumn<QString>("name");
    for (const QString& name : artifactPresetNames())
        QTest::newRow(qPrintable(name)) << name;
}

void tst_MainWindow::presetButtonShowsTheArtifactAndTheFix()
{
    QFETCH(QString, name);
    const ArtifactPreset& preset = artifactPreset(name);
    auto* dock = m_window->propertiesDock();
    auto* button = dock->findChild<QPushButton*>(QStringLiteral("preset.") + name);
    QVERIFY2(button, "every preset has a button in the dock");
    QVERIFY(button->toolTip().contains(QStringLiteral("--preset ") + name));
    const QImage before = scene();
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A), artifactPresetSettings(preset));
    auto* note = dock->findChild<QLabel*>(QStringLiteral("presetNote"));
    QVERIFY(note->isVisibleTo(dock));
    QVERIFY2(note->text().contains(preset.lookFor.toHtmlEscaped().left(30)), qPrintable(note->text()));
    QVERIFY2(differingPixels(before, scene()) > 100, "the preset changes the picture");
    // The dock's fields show the preset's values.
    for (auto it = preset.settings.begin(); it != preset.settings.end(); ++it) {
        if (auto* box = field(it.key()); box && it.value().isDouble() && it.key() != u"light.near")
            QCOMPARE(box->value(), it.value().toDouble());
    }
    auto* fix = dock->findChild<QPushButton*>(QStringLiteral("presetFix"));
    QVERIFY(fix->isVisibleTo(dock) && fix->isEnabled());
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    const auto inView = [scroll](const QWidget* w) {
        const QRect at(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
        return scroll->viewport()->rect().intersects(at);
    };
    QVERIFY(inView(note));
    const int scrolled = scroll->verticalScrollBar()->value();
    QTest::mouseClick(fix, Qt::LeftButton);
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A), artifactPresetFixed(preset));
    QVERIFY(!fix->isEnabled());
    // The explanation stays where the user reads it.
    QCOMPARE(scroll->verticalScrollBar()->value(), scrolled);
    QVERIFY(inView(note) && inView(fix));
}

void tst_MainWindow::presetFromTheCommandLineShowsItsNoteAndFix()
{
    // As `shadowlab --preset light-leak` and `screenshot --preset light-leak` start: the
    // preset's settings set on side A, then its sentences shown without changing them.
    const ArtifactPreset& preset = artifactPreset(QStringLiteral("light-leak"));
    const Settings leaking = applyArtifactPreset(preset, presetSettings(QStringLiteral("seed")));
    m_window->setSettings(Side::A, leaking);
    auto* dock = m_window->propertiesDock();
    auto* note = dock->findChild<QLabel*>(QStringLiteral("presetNote"));
    auto* fix = dock->findChild<QPushButton*>(QStringLiteral("presetFix"));
    QVERIFY(!note->isVisibleTo(dock) && !fix->isVisibleTo(dock));
    dock->showPreset(preset.name);
    QVERIFY(note->isVisibleTo(dock) && fix->isVisibleTo(dock) && fix->isEnabled());
    QVERIFY2(note->text().contains(preset.lookFor.toHtmlEscaped()) && note->text().contains(preset.fix.toHtmlEscaped()), qPrintable(note->text()));
    QCOMPARE(m_window->settings(Side::A), leaking);     // showing changes nothing

    QTest::mouseClick(fix, Qt::LeftButton);
    QVERIFY(settle(*m_window));
    const Settings fixed = m_window->settings(Side::A);
    QCOMPARE(fixed, settingsFromJson(preset.fixSettings, leaking));
    QVERIFY(!fix->isEnabled());
    QCOMPARE(fix->text(), QStringLiteral("Fix Applied"));
    // Undo takes the fix back.
    m_window->undoStack(Side::A)->undo();
    QCOMPARE(m_window->settings(Side::A), leaking);

    QVERIFY_THROWS_EXCEPTION(SettingsError, dock->showPreset(QStringLiteral("acme")));
}

// A field that does nothing with the current settings is greyed and says why; the reason
// goes once a setting makes it count, and the field's own help comes back.
void tst_MainWindow::fieldsTheSettingsIgnoreAreGreyedWithTheReason()
{
    Settings s = m_window->settings(Side::A);
    applySetting(s, "filter.mode", "hw-bilinear");
    applySetting(s, "shadow.virtual", "false");
    m_window->setSettings(Side::A, s);
    auto* dock = m_window->propertiesDock();
    SliderSpinBox* pool = field(QStringLiteral("shadow.virtual_pool"));
    auto* receiverPlane = dock->findChild<QWidget*>(QStringLiteral("bias.receiver_plane"));
    QVERIFY(pool && receiverPlane);
    QVERIFY(!pool->isEnabled());
    QVERIFY2(pool->toolTip().contains("Virtual maps are off: turn on shadow.virtual"), qPrintable(pool->toolTip()));
    QVERIFY2(pool->toolTip().startsWith("<p><b>shadow.virtual_pool</b>"), qPrintable(pool->toolTip()));    // its key first, still
    QVERIFY(!receiverPlane->isEnabled());
    QVERIFY2(receiverPlane->toolTip().contains("one lookup"), qPrintable(receiverPlane->toolTip()));
    applySetting(s, "shadow.virtual", "true");
    applySetting(s, "filter.mode", "pcf");
    m_window->setSettings(Side::A, s);
    QVERIFY(pool->isEnabled() && receiverPlane->isEnabled());
    QVERIFY2(!pool->toolTip().contains("Virtual maps are off") && !pool->toolTip().contains("Not read now"), qPrintable(pool->toolTip()));
    QVERIFY(pool->toolTip().contains(PropertyFields::toolTip("shadow.virtual_pool").left(30)));
}

void tst_MainWindow::everySettingHasADockField()
{
    auto* dock = m_window->propertiesDock();
    for (const SettingKey& key : settingKeys()) {
        if (key.type == u"vec3") {
            for (const char* axis : {".x", ".y", ".z"})
                QVERIFY2(dock->findChild<SliderSpinBox*>(key.key + QLatin1String(axis)), qPrintable(key.key + QLatin1String(axis)));
        } else {
            QWidget* editor = dock->findChild<QWidget*>(key.key);
            QVERIFY2(editor, qPrintable(key.key + QStringLiteral(" has no field in the dock")));
            // The tooltip is the table's help, so the dock explains what the CLI explains (a
            // fitted, read-only field says instead why it cannot be edited).
            // The filter's says what the chosen one does, each choice its own in the list.
            const QString help = key.key == u"filter.mode" ? shadowTechnique(m_window->settings(Side::A).filter.mode).help : key.help;
            if (editor->isEnabled())
                QVERIFY2(editor->toolTip().contains(help.left(30).toHtmlEscaped()), qPrintable(key.key));
        }
    }
    // Shown in the dock as the settings hold them.
    for (const QString& key : {QStringLiteral("light.radius"), QStringLiteral("bias.normal"), QStringLiteral("camera.fov")})
        QCOMPARE(field(key)->value(), settingValue(m_window->settings(Side::A), key).toDouble());
    QCOMPARE(dock->findChild<QComboBox*>(QStringLiteral("light.fit"))->currentText(), settingValue(m_window->settings(Side::A), "light.fit"));
    // Filters by name with their key, each with a tooltip of its own of a sentence or two.
    auto* filter = dock->findChild<QComboBox*>(QStringLiteral("filter.mode"));
    for (const ShadowTechnique& t : shadowTechniques()) {
        const int i = filter->findData(t.key);
        QVERIFY2(i >= 0, qPrintable(t.key));
        QVERIFY2(filter->itemText(i).contains(t.label) && filter->itemText(i).endsWith(t.key), qPrintable(filter->itemText(i)));
        const QString tip = filter->itemData(i, Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains(t.help.toHtmlEscaped()) && tip.size() < 500, qPrintable(tip));
    }
    QVERIFY2(filter->toolTip().size() < 700, qPrintable(filter->toolTip()));
    QCOMPARE(dock->findChild<QCheckBox*>(QStringLiteral("light.stabilize"))->isChecked(), m_window->settings(Side::A).light.stabilize);
}

void tst_MainWindow::cameraFieldsMoveTheSharedCamera()
{
    m_window->setCompareMode(true);
    QVERIFY(settle(*m_window));
    const QImage before = scene();
    SliderSpinBox* x = field(QStringLiteral("camera.position.x"));
    QVERIFY(x);
    x->spinBox()->setValue(x->value() - 3.0);
    x->spinBox()->editingFinished();
    QVERIFY(settle(*m_window));
    const double expected = presetSettings(QStringLiteral("seed")).camera.position.x - 3.0;
    QCOMPARE(m_window->settings(Side::A).camera.position.x, expected);
    QCOMPARE(m_window->settings(Side::B).camera.position.x, expected);  // one camera for both sides
    QVERIFY2(differingPixels(before, scene()) > 100, "the view moved");
    // Orbiting the view writes back into the fields.
    QTest::keyClick(m_window->sceneView(Side::A), Qt::Key_R);
    QVERIFY(settle(*m_window));
    QCOMPARE(x->value(), presetSettings(QStringLiteral("seed")).camera.position.x);
}

void tst_MainWindow::depthLegendSpansTheDepthsInTheMap_data()
{
    QTest::addColumn<QStringList>("assignments");
    QTest::addColumn<double>("nearest");    // distances from the light, world units
    QTest::addColumn<double>("farthest");
    // The occluder scene's light is 6 above the ground, straight down; the board's top is at 1.02,
    // its bottom at 0.98. With back faces only (front faces culled) the ground is not in the map.
    QTest::newRow("ortho, both faces") << QStringList{"light.fit=manual", "bias.cull_front=false", "bias.skip_floors=false"} << 4.98 << 6.0;
    QTest::newRow("ortho, back faces only") << QStringList{"light.fit=manual", "bias.cull_front=true"} << 5.02 << 5.02;
    QTest::newRow("perspective, both faces") << QStringList{"light.fit=manual", "bias.cull_front=false", "bias.skip_floors=false", "light.projection=perspective", "light.fov=60"}
                                             << 4.98 << 6.0;
}

void tst_MainWindow::depthLegendSpansTheDepthsInTheMap()
{
    QFETCH(QStringList, assignments);
    QFETCH(double, nearest);
    QFETCH(double, farthest);
    Settings s = presetSettings(QStringLiteral("occluder"));
    for (const QString& a : assignments)
        applyAssignment(s, a);
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    const std::optional<DepthSpan> span = m_window->depthMapView()->shownSpan();
    QVERIFY2(span, "the legend has a range");
    const LightFrame& light = m_window->sceneView(Side::A)->renderer()->lightFrame();
    // Depth is the distance along the light's axis for ortho and perspective lights alike, so the
    // horizontal board and ground each have one depth.
    const double slack = 0.02;
    QVERIFY2(std::abs(depthToDistance(light, span->nearest) - nearest) <= slack,
             qPrintable(QString("nearest %1 wu, expected %2").arg(depthToDistance(light, span->nearest)).arg(nearest)));
    QVERIFY2(std::abs(depthToDistance(light, span->farthest) - farthest) <= slack,
             qPrintable(QString("farthest %1 wu, expected %2").arg(depthToDistance(light, span->farthest)).arg(farthest)));
    // The picture uses the ramp's whole range: dark near, pale far, and the empty hatching.
    const QImage picture = depthMap();
    QVERIFY2(distinctLevels(picture) > 20, "a legend and a map, not a flat pane");
}

void tst_MainWindow::depthPaneFramesTheMapInWhatTheCameraSees_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("assignments");
    for (const QString& scene : {QStringLiteral("seed"), QStringLiteral("torus"), QStringLiteral("cubes"), QStringLiteral("occluder"), QStringLiteral("city")}) {
        QTest::newRow(qPrintable(scene)) << scene << QStringList{};
        QTest::newRow(qPrintable(scene + " grazing light")) << scene << QStringList{"light.position=-9,0.6,-4"};
    }
    QTest::newRow("seed light above") << "seed" << QStringList{"light.position=0,6,0"};
    QTest::newRow("seed spot") << "seed" << QStringList{"light.type=spot", "light.fov=70"};
    QTest::newRow("seed manual volume") << "seed" << QStringList{"light.fit=manual"};
    QTest::newRow("seed camera at the horizon") << "seed" << QStringList{"camera.position=0,0.3,9", "camera.target=0,0.3,0"};
    QTest::newRow("seed camera looking away") << "seed" << QStringList{"camera.position=0,2,4", "camera.target=0,6,12"};
    QTest::newRow("seed cascades") << "seed" << QStringList{"shadow.cascades=3"};
    QTest::newRow("seed point light") << "seed" << QStringList{"light.type=point", "light.position=0.5,2.6,0.8"};
}

// Before any zoom or pan the depth pane shows the whole map and, around it, what the camera sees
// (cut only where that would shrink the map below half the pane), and the texel readout under
// the pointer names the texel drawn there.
void tst_MainWindow::depthPaneFramesTheMapInWhatTheCameraSees()
{
    QFETCH(QString, scene);
    QFETCH(QStringList, assignments);
    Settings s = presetSettings(scene);
    for (const QString& a : assignments)
        applyAssignment(s, a);
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    DepthMapView* pane = m_window->depthMapView();
    pane->resetZoom();
    QVERIFY(settle(*m_window));
    const Renderer& renderer = *m_window->sceneView(Side::A)->renderer();
    const DepthMapFacts facts = depthMapFacts(renderer, pane->shownSpan());
    const QRectF shown = pane->visibleRect();
    const QRectF map(0.0, 0.0, 1.0, 1.0);
    const QString where = QStringLiteral("shown %1,%2 %3x%4").arg(shown.x()).arg(shown.y()).arg(shown.width()).arg(shown.height());
    QVERIFY2(shown.contains(map), qPrintable(where));
    // The map first: it spans the pane along its tighter side, and fills at least half the
    // pane's area unless the light volume's aspect is far from the pane's.
    QVERIFY2(1.0 / shown.width() >= 0.94 || 1.0 / shown.height() >= 0.94, qPrintable(where));
    const QSize area = DepthMapPicture(pane->size()).mapArea().size();
    const double paneAspect = double(area.width()) / area.height();
    if (std::max(facts.aspect / paneAspect, paneAspect / facts.aspect) < 1.8)
        QVERIFY2(1.0 / (shown.width() * shown.height()) >= 0.5, qPrintable(where));

    // One click away: the map with what the camera sees around it. Every corner of the
    // footprint is then in the picture, or lies beyond the frame's limit.
    m_window->action(QStringLiteral("frameFootprintAction"))->trigger();
    const QRectF framed = pane->visibleRect();
    QVERIFY2(framed.contains(map), qPrintable(where));
    QVERIFY2(1.0 / framed.width() >= 0.45 || 1.0 / framed.height() >= 0.45, qPrintable(where));
    const double limit = DepthMapPicture::kFrameLimit + 1e-9;
    for (const glm::dvec2& p : facts.footprint) {
        const bool beyond = p.x < -limit || p.y < -limit || p.x > 1.0 + limit || p.y > 1.0 + limit;
        QVERIFY2(beyond || framed.contains(QPointF(p.x, p.y)), qPrintable(QStringLiteral("%1: footprint corner %2, %3 cut").arg(where).arg(p.x).arg(p.y)));
    }
    m_window->action(QStringLiteral("fitDepthMapAction"))->trigger();
    QCOMPARE(pane->visibleRect(), shown);
    if (facts.views > 1)
        QVERIFY2(facts.footprint.empty(), "several views: no single footprint drawn over all of them");

    // The texel under the map's centre and near its corner, as the status bar reads them.
    const ShadowMap& shadowMap = renderer.shadowMap();
    const DepthMapPicture picture(pane->size());
    QSignalSpy hovered(pane, &DepthMapView::texelHovered);
    for (const QPointF uv : {QPointF(0.5, 0.5), QPointF(0.1, 0.9)}) {
        const QPointF at = picture.toPixel(uv, shown);
        QMouseEvent move(QEvent::MouseMove, at, pane->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(pane, &move);
        QVERIFY(!hovered.isEmpty());
        const QString text = hovered.last().at(0).toString();
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("texel (\\d+), (\\d+)")).match(text);
        QVERIFY2(m.hasMatch(), qPrintable(text));
        QVERIFY2(std::abs(m.captured(1).toInt() - uv.x() * shadowMap.width()) <= 2 && std::abs(m.captured(2).toInt() - uv.y() * shadowMap.height()) <= 2,
                 qPrintable(QStringLiteral("%1 at map point %2, %3 of %4 x %5").arg(text).arg(uv.x()).arg(uv.y()).arg(shadowMap.width()).arg(shadowMap.height())));
    }
    // Zooming leaves the framing where it was, and Fit goes back to it.
    QWheelEvent wheel(picture.toPixel({0.5, 0.5}, shown), pane->mapToGlobal(picture.toPixel({0.5, 0.5}, shown)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(pane, &wheel);
    QVERIFY(pane->visibleRect().width() < shown.width());
    pane->resetZoom();
    QCOMPARE(pane->visibleRect(), shown);
}

void tst_MainWindow::statusBarShowsMediansAndMeasuresFrames()
{
    auto* timing = m_window->findChild<QLabel*>(QStringLiteral("timingLabel"));
    QVERIFY2(timing->text().contains(QStringLiteral("median of")), qPrintable(timing->text()));
    const bool software = m_window->sceneView(Side::A)->renderer()->rendererString().contains(QStringLiteral("llvmpipe"));
    QCOMPARE(timing->text().contains(QStringLiteral("ms CPU")), software);
    const int before = m_window->sceneView(Side::A)->frameCount();
    const int shadowPasses = m_window->sceneView(Side::A)->renderer()->shadowPassCount();
    m_window->action(QStringLiteral("measureAction"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(m_window->action(QStringLiteral("measureAction"))->isEnabled(), 120000);
    QVERIFY(m_window->sceneView(Side::A)->frameCount() >= before + 100);
    QVERIFY2(m_window->sceneView(Side::A)->renderer()->shadowPassCount() >= shadowPasses + 100, "every measured frame ran the shadow pass");
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("100 frames")), qPrintable(m_window->statusMessage()));
    QVERIFY2(timing->text().contains(QStringLiteral("median of 100")), qPrintable(timing->text()));
    // Other settings start another window: frames of the last ones say nothing about these.
    Settings other = m_window->settings(Side::A);
    applySetting(other, "filter.mode", "pcf");
    m_window->setSettings(Side::A, other);
    QVERIFY(settle(*m_window));
    QVERIFY2(!timing->text().contains(QStringLiteral("median of 100")), qPrintable(timing->text()));
    QVERIFY2(timing->toolTip().contains(QStringLiteral("since the settings last changed")), qPrintable(timing->toolTip()));
    // Compare mode: both sides' cost and the difference, each side's passes in the tooltip.
    m_window->setCompareMode(true);
    QVERIFY(settle(*m_window));
    // No difference claimed before each side has frames enough to tell one from noise.
    if (!timing->text().contains(QStringLiteral("B − A")))
        QVERIFY2(timing->text().contains(QStringLiteral("measuring")), qPrintable(timing->text()));
    m_window->action(QStringLiteral("measureAction"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(m_window->action(QStringLiteral("measureAction"))->isEnabled(), 120000);
    QVERIFY2(timing->text().contains(QStringLiteral("A: ")) && timing->text().contains(QStringLiteral("B − A")), qPrintable(timing->text()));
    QVERIFY2(timing->toolTip().contains(QStringLiteral("Side B: shadow")), qPrintable(timing->toolTip()));

    // Nothing in the status bar is cut off at the window's default size, in either mode, with
    // the long numbers of the city too.
    m_window->resize(1200, 750);
    for (int run = 0; run < 4; ++run) {
        const bool compare = run % 2 == 0;
        if (run == 2)
            m_window->setSettings(Side::A, presetSettings(QStringLiteral("city")));
        m_window->setCompareMode(compare);
        QVERIFY(settle(*m_window));
        QTest::qWait(50);
        int needed = 0;
        for (QLabel* label : m_window->statusBar()->findChildren<QLabel*>()) {
            if (label->isVisible() && !label->text().isEmpty()) {
                needed += label->sizeHint().width();
                QVERIFY2(label->width() >= label->sizeHint().width(),
                         qPrintable(QStringLiteral("'%1' is %2 px wide, needs %3").arg(label->text()).arg(label->width()).arg(label->sizeHint().width())));
            }
        }
        QVERIFY2(needed <= m_window->statusBar()->width(), qPrintable(QStringLiteral("%1 px of labels in %2").arg(needed).arg(m_window->statusBar()->width())));
    }
}

// The timeline: greyed on a still scene; on a moving one, play advances scene.time on both
// sides with the wall clock and the picture moves; pause stops it; a scrub is one undo step;
// the status bar says why the map was drawn.
void tst_MainWindow::timelinePlaysScrubsAndSharesTheClock()
{
    auto* play = m_window->findChild<QAction*>(QStringLiteral("timeline.play"));
    auto* scrubber = m_window->findChild<QSlider*>(QStringLiteral("timeline.scrubber"));
    QVERIFY(play && scrubber);
    QVERIFY2(!play->isEnabled() && !scrubber->isEnabled(), "the seed does not move");
    QVERIFY(scrubber->toolTip().contains(QStringLiteral("Nothing in this scene moves")));

    m_window->setSettings(Side::A, presetSettings(QStringLiteral("swing")));
    QVERIFY(settle(*m_window));
    QVERIFY(play->isEnabled() && scrubber->isEnabled());
    QTest::keyClick(m_window.get(), Qt::Key_D, Qt::ControlModifier);    // compare: both sides share the clock
    QVERIFY(settle(*m_window));
    const QImage still = scene();
    play->trigger();
    QVERIFY(m_window->settings(Side::A).animation.play);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->settings(Side::A).animation.time > 0.3, 10000);
    QCOMPARE(m_window->settings(Side::B).animation.time, m_window->settings(Side::A).animation.time);
    QVERIFY(m_window->findChild<QLabel*>(QStringLiteral("mapLabel"))->text().contains(QStringLiteral("casters moved")));
    QVERIFY(depthMapFacts(*m_window->sceneView(Side::A)->renderer(), std::nullopt).redrawn.contains(QStringLiteral("casters moved")));
    play->trigger();
    QVERIFY(!m_window->settings(Side::A).animation.play);
    QVERIFY(settle(*m_window));
    const double paused = m_window->settings(Side::A).animation.time;
    QTest::qWait(300);
    QCOMPARE(m_window->settings(Side::A).animation.time, paused);

    // A click on the scrubber's groove: one undo step back to where it was.
    QUndoStack* undo = m_window->findChild<QUndoStack*>();
    QVERIFY(undo);
    const int steps = undo->count();
    scrubber->setValue(250);    // a quarter of the swing's 3 s clip: its widest
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A).animation.time, 0.75);
    QCOMPARE(m_window->settings(Side::B).animation.time, 0.75);
    QCOMPARE(undo->count(), steps + 1);
    QVERIFY(differingPixels(scene(), still) > 100);
    undo->undo();
    QVERIFY(settle(*m_window));
    QCOMPARE(m_window->settings(Side::A).animation.time, paused);
}

// shadow.cache=on-demand: as the swing moves the map goes stale, and the status bar and the
// depth pane say so; View > Redraw Cached Shadows draws it again once.
void tst_MainWindow::onDemandCacheRedrawsWhenAsked()
{
    auto* redraw = m_window->findChild<QAction*>(QStringLiteral("redrawCachedShadowsAction"));
    QVERIFY(redraw);
    Settings s = presetSettings(QStringLiteral("swing"));
    applySetting(s, QStringLiteral("shadow.cache"), QStringLiteral("on-demand"));
    s.animation.time = 0.2;
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    s.animation.time = 0.9;
    m_window->setSettings(Side::A, s);
    QVERIFY(settle(*m_window));
    const auto mapText = [&] { return m_window->findChild<QLabel*>(QStringLiteral("mapLabel"))->text(); };
    QVERIFY2(mapText().contains(QStringLiteral("stale")), qPrintable(mapText()));
    const DepthMapFacts stale = depthMapFacts(*m_window->sceneView(Side::A)->renderer(), std::nullopt);
    QCOMPARE(int(stale.cacheTiles.size()), 1);
    QVERIFY(stale.cacheTiles.front().cause == ViewCause::Stale);
    const QImage before = scene();
    redraw->trigger();
    QVERIFY(settle(*m_window));
    QVERIFY2(!mapText().contains(QStringLiteral("stale")), qPrintable(mapText()));
    QVERIFY(differingPixels(scene(), before) > 20);
}

SHADOWLAB_TEST_MAIN(tst_MainWindow)

#include "tst_MainWindow.moc"
