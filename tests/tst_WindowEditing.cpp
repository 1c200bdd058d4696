// Editing in the explorer as a person does it: undo and redo over every kind of settings
// change, one step per slider drag, a history per compare side; the wheel that scrolls the
// dock instead of changing values; the first screenshot on an account with no Pictures
// folder; docks and captions that say what they show at the default size.
#include "AccuracyDock.h"
#include "Application.h"
#include "HeadlessTestMain.h"
#include "MainWindow.h"
#include "PropertiesDock.h"
#include "SceneLibrary.h"
#include "SceneView.h"
#include "SettingsKeys.h"
#include "SliderSpinBox.h"
#include "ViewPane.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QScopeGuard>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTemporaryDir>
#include <QToolTip>
#include <QUndoStack>
#include <QtTest/qtestspontaneevent.h>

#include <memory>

using namespace shadowlab;

namespace {

using Side = MainWindow::Side;

bool settle(const MainWindow& w)
{
    QElapsedTimer total;
    total.start();
    while (total.elapsed() < 20000) {
        QTest::qWait(30);
        if (w.sceneView(Side::A)->frameCount() > 0 && (!w.compareMode() || w.sceneView(Side::B)->frameCount() > 0))
            return true;
    }
    return false;
}

QPoint handleCentre(QSlider* slider)
{
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.subControls = QStyle::SC_None;
    option.activeSubControls = QStyle::SC_None;
    option.orientation = slider->orientation();
    option.maximum = slider->maximum();
    option.minimum = slider->minimum();
    option.tickPosition = slider->tickPosition();
    option.tickInterval = slider->tickInterval();
    option.upsideDown = slider->invertedAppearance();
    option.direction = slider->layoutDirection();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    option.singleStep = slider->singleStep();
    option.pageStep = slider->pageStep();
    return slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
}

// A turn of the wheel as the window system delivers it (spontaneous, so it bubbles up to the
// parents when the widget under the pointer ignores it).
void turnWheel(QWidget* widget, int steps)
{
    const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent wheel(at, widget->mapToGlobal(at), QPoint(), QPoint(0, -120 * steps), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QSpontaneKeyEvent::setSpontaneous(&wheel);
    qApp->notify(widget, &wheel);   // as QTest's mouse functions do: sendEvent() would clear "spontaneous"
}

} // namespace

class tst_WindowEditing : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("ShadowLabTest"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
    }

    void init()
    {
        QSettings().clear();
        m_window = std::make_unique<MainWindow>(MainWindow::Persistence::None);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QApplication::setActiveWindow(m_window.get());
        QVERIFY(settle(*m_window));
    }

    void cleanup() { m_window.reset(); }

    void undoAndRedoAreInTheEditMenu()
    {
        QAction* undo = m_window->action(QStringLiteral("undoAction"));
        QAction* redo = m_window->action(QStringLiteral("redoAction"));
        QVERIFY(undo && redo);
        QCOMPARE(undo->shortcut(), QKeySequence(QKeySequence::Undo));
        QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
        QVERIFY(!undo->isEnabled());     // nothing to undo in a fresh window

        SliderSpinBox* slope = field(QStringLiteral("bias.slope"));
        slope->slider()->setFocus();
        QTest::keyClick(slope->slider(), Qt::Key_PageUp);
        QVERIFY(undo->isEnabled());
        QCOMPARE(undo->text(), QStringLiteral("&Undo Set bias.slope"));
    }

    void ctrlZInATypedFieldUndoesTheSetting()
    {
        // Type a number, press Enter (applied), then Ctrl+Z: the setting goes back, even though
        // the field still has the keyboard focus.
        const Settings original = m_window->settings(Side::A);
        QDoubleSpinBox* box = field(QStringLiteral("bias.min"))->spinBox();
        box->setFocus();
        QVERIFY(box->hasFocus());
        box->selectAll();
        QTest::keyClicks(box, QStringLiteral("0.05"));
        QTest::keyClick(box, Qt::Key_Return);
        QCOMPARE(m_window->settings(Side::A).bias.min, 0.05);
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(m_window->settings(Side::A).bias.min, original.bias.min);
        QCOMPARE(box->value(), original.bias.min);
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(m_window->settings(Side::A).bias.min, 0.05);
    }

    void eachKeyPressIsAStepAndUndoWalksBack()
    {
        const Settings original = m_window->settings(Side::A);
        SliderSpinBox* slope = field(QStringLiteral("bias.slope"));
        slope->slider()->setFocus();
        std::vector<double> values{original.bias.slope};
        for (int i = 0; i < 3; ++i) {
            QTest::keyClick(slope->slider(), Qt::Key_PageUp);
            values.push_back(m_window->settings(Side::A).bias.slope);
        }
        QCOMPARE(m_window->undoStack(Side::A)->count(), 3);
        QAction* undo = m_window->action(QStringLiteral("undoAction"));
        QAction* redo = m_window->action(QStringLiteral("redoAction"));
        for (int i = 2; i >= 0; --i) {
            undo->trigger();
            QCOMPARE(m_window->settings(Side::A).bias.slope, values[std::size_t(i)]);
            QCOMPARE(slope->value(), values[std::size_t(i)]);        // the dock shows it too
        }
        QVERIFY(m_window->settings(Side::A) == original);
        redo->trigger();
        redo->trigger();
        QCOMPARE(m_window->settings(Side::A).bias.slope, values[2]);
        // The view draws what undo restored.
        QVERIFY(settle(*m_window));
        QCOMPARE(m_window->sceneView(Side::A)->renderedSettings()->bias.slope, values[2]);
    }

    void aSliderDragIsOneStep()
    {
        const Settings original = m_window->settings(Side::A);
        SliderSpinBox* size = field(QStringLiteral("bias.slope"));
        QSlider* slider = size->slider();
        const QPoint start = handleCentre(slider);
        QTest::mousePress(slider, Qt::LeftButton, {}, start);
        int changes = 0;
        double last = size->value();
        for (int dx = 4; dx <= 60; dx += 4) {
            QTest::mouseMove(slider, start + QPoint(dx, 0));
            if (size->value() != last)
                ++changes;
            last = size->value();
        }
        QTest::mouseRelease(slider, Qt::LeftButton, {}, start + QPoint(60, 0));
        QVERIFY2(changes > 5, qPrintable(QString::number(changes)));   // the drag went through many values
        QVERIFY(m_window->settings(Side::A).bias.slope != original.bias.slope);
        QCOMPARE(m_window->undoStack(Side::A)->count(), 1);

        // A second drag of the same slider (back, so it moves even if the first reached the
        // end) is a step of its own.
        const double afterFirst = m_window->settings(Side::A).bias.slope;
        const QPoint second = handleCentre(slider);
        QTest::mousePress(slider, Qt::LeftButton, {}, second);
        for (int dx = 4; dx <= 40; dx += 4)
            QTest::mouseMove(slider, second - QPoint(dx, 0));
        QTest::mouseRelease(slider, Qt::LeftButton, {}, second - QPoint(40, 0));
        QVERIFY(m_window->settings(Side::A).bias.slope != afterFirst);
        QCOMPARE(m_window->undoStack(Side::A)->count(), 2);

        m_window->action(QStringLiteral("undoAction"))->trigger();
        QCOMPARE(m_window->settings(Side::A).bias.slope, afterFirst);
        m_window->action(QStringLiteral("undoAction"))->trigger();
        QVERIFY(m_window->settings(Side::A) == original);
    }

    void everyKindOfChangeCanBeUndone()
    {
        const Settings original = m_window->settings(Side::A);
        QUndoStack* stack = m_window->undoStack(Side::A);
        QAction* undo = m_window->action(QStringLiteral("undoAction"));

        // A configuration applied from the accuracy dock (a sweep point or the tuned bias).
        Settings measured = original;
        measured.filter.mode = FilterMode::Pcf;
        measured.filter.kernel = 5;
        measured.map.size = 1024;
        emit m_window->accuracyDock()->applySettingsRequested(measured);
        QVERIFY(m_window->settings(Side::A) == measured);
        QCOMPARE(stack->undoText(), QStringLiteral("Apply measured configuration"));

        // Reset to defaults from the dock.
        m_window->propertiesDock()->findChild<QPushButton*>(QStringLiteral("resetToDefaults"))->click();
        QVERIFY(m_window->settings(Side::A) == original);
        QCOMPARE(stack->undoText(), QStringLiteral("Reset to defaults"));
        undo->trigger();
        QVERIFY(m_window->settings(Side::A) == measured);
        undo->trigger();
        QVERIFY(m_window->settings(Side::A) == original);

        // A choice in a combo box, and a settings file imported.
        auto* filter = m_window->propertiesDock()->findChild<QComboBox*>(QStringLiteral("filter.mode"));
        filter->setCurrentIndex(filter->findData(QStringLiteral("hard")));   // shown as "Hard (1 tap) — hard"
        QVERIFY(m_window->settings(Side::A).filter.mode == FilterMode::Hard);
        const QString file = m_dir.filePath(QStringLiteral("import.json"));
        Settings fileSettings = original;
        fileSettings.map.size = 512;
        saveSettingsFile(file, fileSettings);
        QCOMPARE(m_window->importSettings(file), QString());
        QCOMPARE(m_window->settings(Side::A).map.size, 512);
        undo->trigger();
        QVERIFY(m_window->settings(Side::A).filter.mode == FilterMode::Hard && m_window->settings(Side::A).map.size == original.map.size);
        undo->trigger();
        QVERIFY(m_window->settings(Side::A) == original);

        // Moving the camera is looking, not a setting to undo.
        const int steps = stack->count();
        CameraSettings camera = original.camera;
        camera.position.x += 1.0;
        emit m_window->sceneView(Side::A)->cameraEdited(camera);
        QCOMPARE(stack->count(), steps);
        // ...and undo leaves the camera where it is.
        m_window->action(QStringLiteral("redoAction"))->trigger();
        QCOMPARE(m_window->settings(Side::A).camera.position.x, camera.position.x);

        // A scene chosen in the dock brings its light and camera; undo takes all of it back.
        m_window->propertiesDock()->findChild<QComboBox*>(QStringLiteral("scene"))->setCurrentText(QStringLiteral("torus"));
        QCOMPARE(m_window->settings(Side::A).scene, QStringLiteral("torus"));
        QCOMPARE(stack->undoText(), QStringLiteral("Choose scene torus"));
        undo->trigger();
        QCOMPARE(m_window->settings(Side::A).scene, QStringLiteral("seed"));
        QVERIFY(m_window->settings(Side::A).camera == camera);
        m_window->action(QStringLiteral("redoAction"))->trigger();
        QVERIFY(m_window->settings(Side::A).camera == presetSettings(QStringLiteral("torus")).camera);
    }

    void compareSidesHaveTheirOwnHistory()
    {
        m_window->setCompareMode(true);
        QVERIFY(settle(*m_window));
        const Settings original = m_window->settings(Side::A);
        QAction* undo = m_window->action(QStringLiteral("undoAction"));

        // Side B gets 512², side A hard filtering.
        m_window->selectSide(Side::B);
        field(QStringLiteral("map.size"))->spinBox()->setValue(512);
        QCOMPARE(m_window->settings(Side::B).map.size, 512);
        m_window->selectSide(Side::A);
        auto* filterCombo = m_window->propertiesDock()->findChild<QComboBox*>(QStringLiteral("filter.mode"));
        filterCombo->setCurrentIndex(filterCombo->findData(QStringLiteral("hard")));

        // Undo on A takes back A's edit only.
        undo->trigger();
        QVERIFY(m_window->settings(Side::A) == original);
        QCOMPARE(m_window->settings(Side::B).map.size, 512);
        QVERIFY(!undo->isEnabled());     // A has nothing more
        m_window->selectSide(Side::B);
        QVERIFY(undo->isEnabled());
        undo->trigger();
        QVERIFY(m_window->settings(Side::B) == original);

        // Copy and swap are steps of the side being edited, undone whole.
        m_window->selectSide(Side::A);
        m_window->action(QStringLiteral("redoAction"))->trigger();   // A: hard again
        const Settings a = m_window->settings(Side::A);
        m_window->copyAToB();
        QVERIFY(m_window->settings(Side::B) == a);
        undo->trigger();
        QVERIFY(m_window->settings(Side::B) == original);
        m_window->swapSides();
        QVERIFY(m_window->settings(Side::A) == original && m_window->settings(Side::B) == a);
        undo->trigger();
        QVERIFY(m_window->settings(Side::A) == a && m_window->settings(Side::B) == original);
    }

    void wheelScrollsTheDockUntilAFieldIsClicked()
    {
        auto* scroll = qobject_cast<QScrollArea*>(m_window->propertiesDock()->widget());
        QVERIFY(scroll);
        QScrollBar* bar = scroll->verticalScrollBar();
        QVERIFY2(bar->maximum() > 0, "the dock is taller than the window at this size, so it scrolls");
        bar->setValue(0);
        SliderSpinBox* slope = field(QStringLiteral("bias.slope"));
        auto* filter = m_window->propertiesDock()->findChild<QComboBox*>(QStringLiteral("filter.mode"));
        const Settings before = m_window->settings(Side::A);
        m_window->propertiesDock()->setFocus();

        for (QWidget* under : std::initializer_list<QWidget*>{slope->spinBox(), slope->slider(), filter}) {
            const int scrolled = bar->value();
            turnWheel(under, 1);
            QVERIFY2(m_window->settings(Side::A) == before, qPrintable(under->metaObject()->className()));
            QVERIFY2(bar->value() > scrolled || bar->value() == bar->maximum(), qPrintable(under->metaObject()->className()));
            bar->setValue(0);
        }

        // Clicked (focused), the field takes the wheel.
        slope->spinBox()->setFocus();
        QVERIFY(slope->spinBox()->hasFocus());
        turnWheel(slope->spinBox(), -1);
        QVERIFY(m_window->settings(Side::A).bias.slope > before.bias.slope);
        filter->setFocus();
        turnWheel(filter, 1);
        QVERIFY(m_window->settings(Side::A).filter.mode != before.filter.mode);
    }

    void firstScreenshotWorksWithoutAPicturesFolder()
    {
        QTemporaryDir home;
        const QByteArray oldHome = qgetenv("HOME"), oldConfig = qgetenv("XDG_CONFIG_HOME");
        qputenv("HOME", home.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral(".config")).toUtf8());
        auto restore = qScopeGuard([&] {
            qputenv("HOME", oldHome);
            oldConfig.isNull() ? qunsetenv("XDG_CONFIG_HOME") : qputenv("XDG_CONFIG_HOME", oldConfig);
        });
        QVERIFY(!QFileInfo::exists(home.filePath(QStringLiteral("Pictures"))));
        const QString folder = m_window->screenshotFolder();
        QCOMPARE(folder, home.filePath(QStringLiteral("Pictures")));
        QVERIFY(QFileInfo(folder).isDir());      // made for the user
        const QString shot = QDir(folder).filePath(QStringLiteral("first.png"));
        QCOMPARE(m_window->saveScreenshot(ScreenshotDialog::Target::SceneView, shot), QString());
        QVERIFY(!QImage(shot).isNull());

        // A "Pictures" that cannot be a folder: the home folder it is.
        QTemporaryDir other;
        qputenv("HOME", other.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", other.filePath(QStringLiteral(".config")).toUtf8());
        QFile blocker(other.filePath(QStringLiteral("Pictures")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        std::unique_ptr<MainWindow> fresh = std::make_unique<MainWindow>(MainWindow::Persistence::None);
        QCOMPARE(fresh->screenshotFolder(), other.path());
    }

    void docksSayWhichSideTheyShow()
    {
        QCOMPARE(m_window->propertiesDock()->windowTitle(), QStringLiteral("Properties"));
        m_window->setCompareMode(true);
        QCOMPARE(m_window->propertiesDock()->windowTitle(), QStringLiteral("Properties — side A"));
        m_window->selectSide(Side::B);
        QCOMPARE(m_window->propertiesDock()->windowTitle(), QStringLiteral("Properties — side B"));
        QCOMPARE(m_window->accuracyDock()->windowTitle(), QStringLiteral("Accuracy — A and B"));
        m_window->setCompareMode(false);
        QCOMPARE(m_window->propertiesDock()->windowTitle(), QStringLiteral("Properties"));
    }

    void captionsAreWholeAtTheDefaultSize()
    {
        // The window as it first opens, in compare mode too, where each view is narrowest.
        for (bool compare : {false, true}) {
            m_window->setCompareMode(compare);
            QVERIFY(settle(*m_window));
            QTest::qWait(50);
            for (ViewPane* pane : m_window->findChildren<ViewPane*>()) {
                if (!pane->isVisible())
                    continue;
                auto* caption = pane->findChild<QLabel*>();
                QVERIFY(caption);
                QVERIFY2(caption->height() >= caption->heightForWidth(caption->width()),
                         qPrintable(QStringLiteral("%1: %2 px high, needs %3").arg(caption->text()).arg(caption->height()).arg(caption->heightForWidth(caption->width()))));
            }
        }
    }

    void chartTooltipsAreReadable()
    {
        // The chart's tooltip, shown for the chart as hovering it does: an opaque, light panel
        // with dark text (a transparent one draws as a black bar on most X servers).
        auto* chart = m_window->accuracyDock()->findChild<QWidget*>(QStringLiteral("sweepChart"));
        QVERIFY(chart);
        m_window->accuracyDock()->raise();
        QVERIFY(QTest::qWaitFor([&] { return chart->isVisible(); }));
        QToolTip::showText(chart->mapToGlobal(chart->rect().center()), chart->toolTip(), chart);
        QWidget* tip = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w->inherits("QTipLabel") && w->isVisible())
                    tip = w;
            return tip != nullptr;
        }));
        const QImage image = tip->grab().toImage().convertToFormat(QImage::Format_ARGB32);
        int light = 0, dark = 0, seeThrough = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb p = image.pixel(x, y);
                seeThrough += qAlpha(p) < 250 ? 1 : 0;
                light += qAlpha(p) >= 250 && qGray(p) > 180 ? 1 : 0;
                dark += qAlpha(p) >= 250 && qGray(p) < 90 ? 1 : 0;
            }
        const int pixels = image.width() * image.height();
        QToolTip::hideText();
        QVERIFY2(seeThrough == 0, qPrintable(QStringLiteral("%1 of %2 pixels see-through").arg(seeThrough).arg(pixels)));
        QVERIFY2(light > pixels / 2 && dark > 20, qPrintable(QStringLiteral("%1 light, %2 dark of %3").arg(light).arg(dark).arg(pixels)));
    }

private:
    SliderSpinBox* field(const QString& key) const { return m_window->propertiesDock()->findChild<SliderSpinBox*>(key); }

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

SHADOWLAB_TEST_MAIN(tst_WindowEditing)
#include "tst_WindowEditing.moc"
