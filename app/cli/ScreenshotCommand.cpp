#include "AccuracyDock.h"
#include "CliSupport.h"
#include "Commands.h"
#include "DepthMapView.h"
#include "MainWindow.h"
#include "ImageFile.h"
#include "OutputFile.h"
#include "PropertiesDock.h"
#include "RenderError.h"
#include "SceneLibrary.h"
#include "SceneView.h"
#include "SettingsKeys.h"

#include <QApplication>
#include <QDeadlineTimer>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>

namespace shadowlab::cli {

namespace {

constexpr int kTimeoutMs = 60000;
// The window grabbed as an image, its views' framebuffers and the composed backing store:
// about 40 bytes per pixel, 670 MB at the maximum.
const SizeLimits kScreenshotSize{{1, 1}, {4096, 4096}, QStringLiteral("screenshot keeps about 40 bytes per pixel in memory")};
constexpr int kSettledMs = 200;     // no new frame for this long: the window is done drawing

int totalFrames(const MainWindow& window)
{
    return window.sceneView(MainWindow::Side::A)->frameCount() + window.sceneView(MainWindow::Side::B)->frameCount()
        + window.depthMapView()->frameCount();
}

// Runs the event loop until every visible view has drawn and then nothing has drawn for a while;
// a scene that plays never stops drawing, so there a while after every view has drawn is the moment.
void waitUntilRendered(const MainWindow& window)
{
    const Settings& shown = window.settings(MainWindow::Side::A);
    const bool playing = shown.animation.play && sceneMoves(shown.scene);
    const QDeadlineTimer deadline(kTimeoutMs);
    auto drawn = [&window] {
        return window.sceneView(MainWindow::Side::A)->frameCount() > 0
            && (!window.compareMode() || window.sceneView(MainWindow::Side::B)->frameCount() > 0)
            && window.depthMapView()->frameCount() > 0;
    };
    int frames = -1;
    QDeadlineTimer settled(kSettledMs);
    while (!deadline.hasExpired()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (totalFrames(window) != frames && !(playing && drawn())) {
            frames = totalFrames(window);
            settled.setRemainingTime(kSettledMs);
        } else if (drawn() && settled.hasExpired()) {
            return;
        }
    }
    throw RenderError(QStringLiteral("the window did not finish drawing within %1 s").arg(kTimeoutMs / 1000));
}

} // namespace

int runScreenshot(const QStringList& arguments)
{
    return guarded(QStringLiteral("screenshot"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("Build the explorer window offscreen, let it render, and save the whole window as PNG."));
        parser.addHelpOption();
        addSettingsOptions(parser);
        parser.addOption({QStringLiteral("compare"), QStringLiteral("Compare mode: sides A and B side by side.")});
        parser.addOption({QStringLiteral("set-b"), QStringLiteral("With --compare: a setting of side B on top of A's (repeatable)."),
                          QStringLiteral("key=value")});
        parser.addOption({QStringLiteral("accuracy"),
                          QStringLiteral("Show the accuracy dock after Compare with reference (both sides in compare mode), its errors over the views.")});
        parser.addOption({QStringLiteral("size"), QStringLiteral("Window size (default 1200x750)."), QStringLiteral("WxH"),
                          QStringLiteral("1200x750")});
        parser.addOption({QStringLiteral("out"), QStringLiteral("PNG of the window."), QStringLiteral("file.png")});
        if (!parseArguments(parser, QStringLiteral("screenshot"), arguments))
            return kExitOk;
        if (!parser.isSet(QStringLiteral("out")))
            throw UsageError(QStringLiteral("say where to write: --out window.png"));
        const QString path = parser.value(QStringLiteral("out"));
        checkOutputFile(path, QStringLiteral("--out"));
        if (parser.isSet(QStringLiteral("set-b")) && !parser.isSet(QStringLiteral("compare")))
            throw UsageError(QStringLiteral("--set-b describes side B; add --compare"));
        if (!qobject_cast<QApplication*>(QCoreApplication::instance()))
            throw RenderError(QStringLiteral("the screenshot command needs a QApplication"));

        const Settings a = settingsFromOptions(parser);
        Settings b = a;
        for (const QString& assignment : parser.values(QStringLiteral("set-b")))
            applyAssignment(b, assignment);
        ensureValid(b);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kScreenshotSize);

        MainWindow window(MainWindow::Persistence::None);
        window.setCompareMode(parser.isSet(QStringLiteral("compare")));
        // Below the layout's minimum the views get no room and never draw.
        const QSize minimum = window.minimumSizeHint().expandedTo(window.minimumSize());
        if (size.width() < minimum.width() || size.height() < minimum.height())
            throw UsageError(QStringLiteral("--size: %1x%2 is smaller than the explorer window can be laid out%3; the minimum is %4x%5")
                                 .arg(size.width())
                                 .arg(size.height())
                                 .arg(parser.isSet(QStringLiteral("compare")) ? QStringLiteral(" in compare mode") : QString())
                                 .arg(minimum.width())
                                 .arg(minimum.height()));
        window.setSettings(MainWindow::Side::A, a);
        window.setSettings(MainWindow::Side::B, b);
        // What to look for and the fix, as the dock's preset buttons show them.
        if (parser.isSet(QStringLiteral("preset")))
            window.propertiesDock()->showPreset(parser.value(QStringLiteral("preset")));
        window.resize(size);
        window.show();
        waitUntilRendered(window);
        if (parser.isSet(QStringLiteral("accuracy"))) {
            // As a user would: the dock to the front, Compare, and wait for the measurement.
            AccuracyDock* dock = window.accuracyDock();
            dock->raise();
            waitUntilRendered(window);
            auto* compare = dock->findChild<QPushButton*>(QStringLiteral("compareButton"));
            compare->click();
            const QDeadlineTimer deadline(kTimeoutMs);
            while (dock->isBusy() && !deadline.hasExpired())
                QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            if (dock->isBusy())
                throw RenderError(QStringLiteral("the comparison with the reference did not finish within %1 s").arg(kTimeoutMs / 1000));
            if (const auto* status = dock->findChild<QLabel*>(QStringLiteral("status")); status && status->isVisible() && !status->text().isEmpty())
                err() << "screenshot: " << status->text() << Qt::endl;
            waitUntilRendered(window);
        }

        const QImage image = window.grab().toImage();
        writeOutputFile(path, encodePng(image));
        out() << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << image.width() << "x" << image.height() << ")" << Qt::endl;
        return kExitOk;
    });
}

} // namespace shadowlab::cli
