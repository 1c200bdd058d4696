// The window never blocks on a file and a crash loses nothing: a file is read in the background
// with progress and Cancel while the current scene stays usable; whatever the importer does
// (crash, hang, cancel) the window keeps its scene and says what happened; the session is on
// disk within a second of a change; after a crash the next start offers to restore it, and does
// not reopen the file that was being opened.
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "ImportLimits.h"
#include "MainWindow.h"
#include "SceneLibrary.h"
#include "SceneOpener.h"
#include "SceneView.h"
#include "SessionAutosave.h"
#include "SettingsKeys.h"
#include "StopSignals.h"
#include "TestFiles.h"
#include "TestPictures.h"

#include <QDir>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>

#include <csignal>

#include <unistd.h>

using namespace shadowlab;

namespace {

const QString kModels = kTestModels;

QString storedSettings(const QString& side)
{
    QSettings store;
    store.sync();   // read what is on disk now
    return store.value(QStringLiteral("settings/") + side).toString();
}

QMessageBox* box(const MainWindow& window, const QString& name)
{
    return window.findChild<QMessageBox*>(name);
}

} // namespace

class tst_SessionRecovery : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);   // QSettings in a test location, not the user's
        QCoreApplication::setOrganizationName(QStringLiteral("ShadowLabTests"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_SessionRecovery"));
        m_headless = std::make_unique<HeadlessRenderer>();
    }
    void init()
    {
        QSettings().clear();
        QSettings().sync();
        qunsetenv("SHADOWLAB_IMPORT_WORKER");
        setImportLimits({});
    }
    void cleanupTestCase() { m_headless.reset(); }

    void openingRunsInTheBackgroundAndCancels()
    {
        qputenv("SHADOWLAB_IMPORT_WORKER", SHADOWLAB_FAKE_WORKER);
        QTemporaryDir dir;
        const QString slow = writeFile(dir, QStringLiteral("large.glb"), "slow\n");
        MainWindow window(MainWindow::Persistence::None);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const Settings before = window.settings(MainWindow::Side::A);

        window.openSceneInBackground(slow);
        auto* progress = window.findChild<QWidget*>(QStringLiteral("openSceneProgress"));
        QVERIFY(progress && progress->isVisible());
        QVERIFY(progress->findChild<QLabel*>()->text().contains(QStringLiteral("large.glb")));
        QTRY_VERIFY(progress->findChild<QProgressBar*>()->value() >= 10);
        keepPicture(&window, QStringLiteral("opening-in-background"));
        // The current scene stays usable meanwhile: an edit applies and is drawn.
        Settings edited = before;
        edited.bias.slope *= 2.0;
        window.setSettings(MainWindow::Side::A, edited);
        QTRY_VERIFY(window.sceneView(MainWindow::Side::A)->renderedSettings()
                    && window.sceneView(MainWindow::Side::A)->renderedSettings()->bias.slope == edited.bias.slope);

        QElapsedTimer clock;
        clock.start();
        QTest::mouseClick(progress->findChild<QPushButton*>(QStringLiteral("cancelOpenButton")), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!window.sceneOpener()->isBusy(), 2000);
        QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY(!progress->isVisible());
        QCOMPARE(window.settings(MainWindow::Side::A), edited);
        QVERIFY2(window.statusMessage().contains(QStringLiteral("Cancelled: large.glb not opened")),
                 qPrintable(window.statusMessage()));
        keepPicture(&window, QStringLiteral("opening-cancelled"));
        QVERIFY(window.recentScenes().isEmpty());

        // Left alone, the same file opens.
        window.openSceneInBackground(slow);
        QTRY_VERIFY_WITH_TIMEOUT(!window.sceneOpener()->isBusy(), 20000);
        QCOMPARE(window.settings(MainWindow::Side::A).scene, QFileInfo(slow).absoluteFilePath());
    }

    void importerFailuresKeepTheScene_data()
    {
        QTest::addColumn<QByteArray>("mode");
        QTest::addColumn<QString>("says");
        QTest::addColumn<QString>("retry");     // the box's offer to raise the limit that stopped it, if any
        QTest::newRow("crash") << QByteArray("crash") << QStringLiteral("crashed reading it (signal 11") << QString();
        QTest::newRow("hang") << QByteArray("sleep") << QStringLiteral("took longer than 1.5 s") << QStringLiteral("Try Again with 60 s");
        QTest::newRow("garbage") << QByteArray("garbage") << QStringLiteral("does not hold together") << QString();
    }
    void importerFailuresKeepTheScene()
    {
        QFETCH(QByteArray, mode);
        QFETCH(QString, says);
        QFETCH(QString, retry);
        qputenv("SHADOWLAB_IMPORT_WORKER", SHADOWLAB_FAKE_WORKER);
        setImportLimits({.timeSeconds = 1.5});
        QTemporaryDir dir;
        const QString file = writeFile(dir, QStringLiteral("engine.ply"), mode + "\n");
        MainWindow window(MainWindow::Persistence::None);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const Settings before = window.settings(MainWindow::Side::A);
        window.openSceneInBackground(file);
        QTRY_VERIFY_WITH_TIMEOUT(box(window, QStringLiteral("openErrorBox")), 10000);
        const QString text = box(window, QStringLiteral("openErrorBox"))->text();
        keepPicture(&window, QStringLiteral("importer-%1-window").arg(QString::fromLatin1(mode)));
        keepPicture(box(window, QStringLiteral("openErrorBox")), QStringLiteral("importer-%1-message").arg(QString::fromLatin1(mode)));
        QVERIFY2(text.contains(says) && text.contains(QStringLiteral("engine.ply")) && text.contains(QStringLiteral("The current scene stays")),
                 qPrintable(text));
        QCOMPARE(window.settings(MainWindow::Side::A), before);
        QVERIFY(window.sceneView(MainWindow::Side::A)->renderedSettings());
        QCOMPARE(window.sceneView(MainWindow::Side::A)->renderedSettings()->scene, before.scene);
        QVERIFY(window.recentScenes().isEmpty());
        // The window's words, not the command line's: a limit is raised from the box itself.
        QVERIFY2(!text.contains(QStringLiteral("--import")), qPrintable(text));
        auto* again = box(window, QStringLiteral("openErrorBox"))->findChild<QPushButton*>(QStringLiteral("retryButton"));
        QCOMPARE(again != nullptr, !retry.isEmpty());
        if (again) {
            QCOMPARE(again->text(), retry);
            QTest::mouseClick(again, Qt::LeftButton);
            QCOMPARE(importLimits().timeSeconds, 60.0);
            QVERIFY(window.sceneOpener()->isBusy());    // trying again, with the time it now has
            window.sceneOpener()->cancel();
            QTRY_VERIFY_WITH_TIMEOUT(!window.sceneOpener()->isBusy(), 5000);
            setImportLimits({.timeSeconds = 1.5});
        }
    }

    void sessionIsOnDiskWithinASecond()
    {
        MainWindow window(MainWindow::Persistence::Restore);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        Settings edited = window.settings(MainWindow::Side::A);
        edited.bias.slope = 0.0123;
        window.setSettings(MainWindow::Side::A, edited);
        window.setCompareMode(true);
        QTRY_VERIFY_WITH_TIMEOUT(storedSettings(QStringLiteral("A")).contains(QStringLiteral("0.0123")), 2500);
        QSettings store;
        QCOMPARE(store.value(QStringLiteral("view/compare")).toBool(), true);
        QCOMPARE(store.value(QStringLiteral("session/running")).toBool(), true);
        // Never closed: the next window is a start after a crash.
    }

    // A logout, a shutdown, `kill` or Ctrl+C is a close, not a crash: the last edit (still
    // inside its second before the autosave) is saved, the session is marked as ended, and the
    // next start restores it without asking. (The process's exit code 0 is stop-signal-test.py's
    // to check, on a virtual display.)
    void stopSignalClosesAsTheUserWould_data()
    {
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("then");      // a second, other signal at once (0: none)
        QTest::newRow("SIGTERM") << SIGTERM << 0;
        QTest::newRow("SIGINT") << SIGINT << 0;
        QTest::newRow("SIGHUP") << SIGHUP << 0;
        QTest::newRow("logout: SIGTERM and SIGHUP together") << SIGTERM << SIGHUP;
    }
    void stopSignalClosesAsTheUserWould()
    {
        QFETCH(int, signal);
        QFETCH(int, then);
        {
            for (int s : {SIGTERM, SIGINT, SIGHUP})
                std::signal(s, SIG_DFL);    // as a desktop or a terminal starts it (nohup would ignore SIGHUP)
            MainWindow window(MainWindow::Persistence::Restore);
            StopSignals stop;
            QSignalSpy stopping(&stop, &StopSignals::stopping);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QTest::qWait(2 * SessionAutosave::kDelayMs);   // what is on disk is the start's
            Settings edited = window.settings(MainWindow::Side::A);
            edited.bias.slope = 0.0789;
            window.setSettings(MainWindow::Side::A, edited);
            QVERIFY(!storedSettings(QStringLiteral("A")).contains(QStringLiteral("0.0789")));
            QCOMPARE(::kill(::getpid(), signal), 0);
            if (then != 0)
                QCOMPARE(::kill(::getpid(), then), 0);   // before the window has begun to close: not a second request
            QTRY_VERIFY_WITH_TIMEOUT(!window.isVisible(), 2000);
            QCOMPARE(stopping.count(), 1);
            QCOMPARE(stopping.first().first().toInt(), signal);
            QVERIFY(storedSettings(QStringLiteral("A")).contains(QStringLiteral("0.0789")));
            QCOMPARE(QSettings().value(QStringLiteral("session/running")).toBool(), false);
        }
        MainWindow window(MainWindow::Persistence::Restore);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::qWait(300);
        QVERIFY(!box(window, QStringLiteral("restoreSessionBox")));
        QCOMPARE(window.settings(MainWindow::Side::A).bias.slope, 0.0789);
        keepPicture(&window, QStringLiteral("start-after-sigterm"));
    }

    void crashOffersToRestore()
    {
        {
            MainWindow window(MainWindow::Persistence::Restore);
            Settings edited = window.settings(MainWindow::Side::A);
            edited.bias.slope = 0.0456;
            applySetting(edited, QStringLiteral("filter.mode"), QStringLiteral("pcf"));
            window.setSettings(MainWindow::Side::A, edited);
            window.setCompareMode(true);
            QTRY_VERIFY_WITH_TIMEOUT(storedSettings(QStringLiteral("A")).contains(QStringLiteral("0.0456")), 2500);
        }
        // The window above was never closed, as after a kill -9: the running marker is still set.
        QVERIFY(QSettings().value(QStringLiteral("session/running")).toBool());

        MainWindow window(MainWindow::Persistence::Restore);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTRY_VERIFY(box(window, QStringLiteral("restoreSessionBox")));
        QVERIFY(box(window, QStringLiteral("restoreSessionBox"))->text().contains(QStringLiteral("did not close properly")));
        // Until the user says so, nothing of the crashed session is applied, and nothing is saved
        // over it, however long the question stays open.
        QCOMPARE(window.settings(MainWindow::Side::A).bias.slope, presetSettings(QStringLiteral("seed")).bias.slope);
        QVERIFY(!window.compareMode());
        QTest::qWait(2 * SessionAutosave::kDelayMs);
        QVERIFY(storedSettings(QStringLiteral("A")).contains(QStringLiteral("0.0456")));
        box(window, QStringLiteral("restoreSessionBox"))->findChild<QPushButton*>(QStringLiteral("restoreSessionButton"))->click();
        QCOMPARE(window.settings(MainWindow::Side::A).bias.slope, 0.0456);
        QCOMPARE(settingValue(window.settings(MainWindow::Side::A), QStringLiteral("filter.mode")), QStringLiteral("pcf"));
        QVERIFY(window.compareMode());
    }

    void crashWhileOpeningDoesNotReopen()
    {
        const QString model = kModels + QStringLiteral("OBJ/box.obj");
        {
            MainWindow window(MainWindow::Persistence::Restore);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QCOMPARE(window.openScene(model), QString());
            QTRY_VERIFY_WITH_TIMEOUT(storedSettings(QStringLiteral("A")).contains(QStringLiteral("box.obj")), 2500);
        }
        // What a crash while the model was being drawn for the first time leaves behind.
        QSettings store;
        store.setValue(QStringLiteral("session/running"), true);
        store.setValue(QStringLiteral("session/opening"), model);
        store.sync();

        MainWindow window(MainWindow::Persistence::Restore);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTRY_VERIFY(box(window, QStringLiteral("restoreSessionBox")));
        QVERIFY(box(window, QStringLiteral("restoreSessionBox"))->text().contains(QStringLiteral("box.obj was being opened")));
        keepPicture(box(window, QStringLiteral("restoreSessionBox")), QStringLiteral("restore-after-crash"));
        QTest::qWait(2 * SessionAutosave::kDelayMs);
        QVERIFY(storedSettings(QStringLiteral("A")).contains(QStringLiteral("box.obj")));   // what Restore would bring back
        box(window, QStringLiteral("restoreSessionBox"))->findChild<QPushButton*>(QStringLiteral("restoreSessionButton"))->click();
        QTest::qWait(300);
        QVERIFY(!window.sceneOpener()->isBusy());
        QCOMPARE(window.settings(MainWindow::Side::A).scene, QStringLiteral("seed"));
        QVERIFY(window.recentScenes().contains(model));   // one click away, if the user trusts it
    }

    void cleanStartRestoresAFileSceneInTheBackground()
    {
        const QString model = kModels + QStringLiteral("OBJ/box.obj");
        {
            MainWindow window(MainWindow::Persistence::Restore);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QCOMPARE(window.openScene(model), QString());
            window.close();     // a clean end
        }
        MainWindow window(MainWindow::Persistence::Restore);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(!box(window, QStringLiteral("restoreSessionBox")));
        QTRY_COMPARE(window.settings(MainWindow::Side::A).scene, model);
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(tst_SessionRecovery)
#include "tst_SessionRecovery.moc"
