#include "CliSupport.h"
#include "Commands.h"
#include "FrameStatsText.h"
#include "HeadlessPlatform.h"
#include "HeadlessRenderer.h"
#include "ImageFile.h"
#include "OutputFile.h"
#include "RenderError.h"

#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>

namespace shadowlab::cli {

namespace {

// The image, its depth buffer and the read-back take about 16 bytes per pixel: 1 GiB at most.
const SizeLimits kRenderSize{{1, 1}, {8192, 8192}, QStringLiteral("render keeps about 16 bytes per pixel in memory")};

// Without --out the scene goes to shadowlab-<scene>.png in the current folder; a file of that
// name is never overwritten: the next free shadowlab-<scene>-2.png, -3, ... is taken instead.
// Only [A-Za-z0-9._-] in the name ("city:50" is shadowlab-city-50.png), so it travels well.
QString defaultScenePath(const QString& scene)
{
    const QString base = QStringLiteral("shadowlab-")
                         + QFileInfo(scene).completeBaseName().replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]+")), QStringLiteral("-"));
    QString name = base + QStringLiteral(".png");
    for (int n = 2; QFileInfo::exists(name); ++n)
        name = QStringLiteral("%1-%2.png").arg(base).arg(n);
    return name;
}

void report(const QString& path, QSize size)
{
    out() << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << size.width() << "x" << size.height() << ")" << Qt::endl;
}

// What the frame did, line by line: its texels, the warp, the virtual map's pages, the cache,
// the cascades' splits, what the fit cut and the platform.
void printFrameFacts(const Renderer& renderer)
{
    out() << formatTexelLine(renderer.lastFrame()) << Qt::endl;
    if (const QString warp = warpStatusText(renderer.lastFrame()); !warp.isEmpty())
        out() << warp << Qt::endl;
    if (const QString pages = virtualMapStatusText(renderer.lastFrame()); !pages.isEmpty())
        out() << pages << Qt::endl;
    if (const QString cache = cacheStatusText(renderer.lastFrame()); !cache.isEmpty())
        out() << cache << Qt::endl;
    if (const ShadowViewFrames& views = renderer.shadowViews(); views.set.cascaded) {
        QStringList splits;
        for (const ShadowView& view : views.set.views)
            splits << QString::number(view.splitNear, 'g', 4);
        splits << QString::number(views.set.views.back().splitFar, 'g', 4);
        out() << "cascades split at " << splits.join(QStringLiteral(", ")) << " world units from the camera"
              << (renderer.visibleDepthRange() ? " (sdsm: the depths this frame draws)" : "") << Qt::endl;
    }
    printFitWarnings(renderer.lastFit());
    if (const QString backend = activeHeadlessBackend(); !backend.isEmpty())
        out() << "headless platform: " << backend << ", " << renderer.rendererString() << Qt::endl;
}

} // namespace

int runRender(const QStringList& arguments)
{
    return guarded(QStringLiteral("render"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("Render a scene headless to PNG."));
        parser.addHelpOption();
        addSettingsOptions(parser);
        parser.addOption({QStringLiteral("size"), QStringLiteral("Image size (default 1280x720)."), QStringLiteral("WxH"),
                          QStringLiteral("1280x720")});
        parser.addOption({QStringLiteral("out"),
                          QStringLiteral("PNG of the lit scene (default: shadowlab-<scene>.png in the current folder, numbered -2, -3, ... "
                                         "rather than overwriting; with only --depth-out, no scene image)."),
                          QStringLiteral("file.png")});
        parser.addOption({QStringLiteral("depth-out"),
                          QStringLiteral("PNG of the light's shadow map as the explorer shows it: colour ramp, legend, light volume and camera outline."),
                          QStringLiteral("file.png")});
        parser.addOption({QStringLiteral("play"),
                          QStringLiteral("Play the scene for n frames at 60 a second before the one written, ending at scene.time, as "
                                         "the explorer would have drawn them: what shadow.cache kept and why shows in --depth-out's "
                                         "colours and the cache line (default 0)."),
                          QStringLiteral("n"), QStringLiteral("0")});
        if (!parseArguments(parser, QStringLiteral("render"), arguments))
            return kExitOk;
        const Settings settings = settingsFromOptions(parser);
        const bool writeScene = parser.isSet(QStringLiteral("out")) || !parser.isSet(QStringLiteral("depth-out"));
        const bool writeDepth = parser.isSet(QStringLiteral("depth-out"));
        // Every output is checked before any work, so one that cannot be written leaves the others alone.
        const QString scenePath = parser.isSet(QStringLiteral("out")) ? parser.value(QStringLiteral("out")) : defaultScenePath(settings.scene);
        const QString depthPath = parser.value(QStringLiteral("depth-out"));
        if (writeScene)
            checkOutputFile(scenePath, QStringLiteral("--out"));
        if (writeDepth)
            checkOutputFile(depthPath, QStringLiteral("--depth-out"));
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kRenderSize);
        if (writeDepth && !settings.shadow.enabled)
            throw UsageError(QStringLiteral("--depth-out needs shadows; drop --set shadow.enabled=false"));

        const int play = parseCount(parser.value(QStringLiteral("play")), QStringLiteral("play"), 0, 10000);
        HeadlessRenderer headless;
        for (int k = play; k >= 1; --k) {
            Settings before = settings;
            before.animation.time = std::max(0.0, settings.animation.time - k / 60.0);
            headless.renderFrame(before, size);
        }
        const QImage scene = headless.renderScene(settings, size);
        printFrameFacts(headless.renderer());
        QByteArray scenePng, depthPng;
        QSize depthSize;
        if (writeScene)
            scenePng = encodePng(scene);
        if (writeDepth) {
            const QImage depth = headless.renderDepthPicture(std::clamp(settings.map.size, 320, 1024));
            depthSize = depth.size();
            depthPng = encodePng(depth);
        }
        if (writeScene) {
            writeOutputFile(scenePath, scenePng);
            report(scenePath, scene.size());
        }
        if (writeDepth) {
            writeOutputFile(depthPath, depthPng);
            report(depthPath, depthSize);
        }
        return kExitOk;
    });
}

} // namespace shadowlab::cli
