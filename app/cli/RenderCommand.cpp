#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessPlatform.h"
#include "HeadlessRenderer.h"
#include "ImageFile.h"
#include "OutputFile.h"
#include "RenderError.h"

#include <QFileInfo>

#include <algorithm>

namespace shadowlab::cli {

namespace {

// The image, its depth buffer and the read-back take about 16 bytes per pixel: 1 GiB at most.
const SizeLimits kRenderSize{{1, 1}, {8192, 8192}, QStringLiteral("render keeps about 16 bytes per pixel in memory")};

void report(const QString& path, QSize size)
{
    out() << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << size.width() << "x" << size.height() << ")" << Qt::endl;
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
        parser.addOption({QStringLiteral("out"), QStringLiteral("PNG of the lit scene."), QStringLiteral("file.png")});
        parser.addOption({QStringLiteral("depth-out"), QStringLiteral("PNG of the light's shadow map as the explorer shows it: colour ramp, legend, light volume and camera outline."), QStringLiteral("file.png")});
        if (!parseArguments(parser, QStringLiteral("render"), arguments))
            return kExitOk;
        if (!parser.isSet(QStringLiteral("out")) && !parser.isSet(QStringLiteral("depth-out")))
            throw UsageError(QStringLiteral("say where to write: --out scene.png and/or --depth-out depth.png"));

        // Every output is checked before any work, so one that cannot be written leaves the others alone.
        const QString scenePath = parser.value(QStringLiteral("out"));
        const QString depthPath = parser.value(QStringLiteral("depth-out"));
        if (parser.isSet(QStringLiteral("out")))
            checkOutputFile(scenePath, QStringLiteral("--out"));
        if (parser.isSet(QStringLiteral("depth-out")))
            checkOutputFile(depthPath, QStringLiteral("--depth-out"));
        const Settings settings = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kRenderSize);
        if (parser.isSet(QStringLiteral("depth-out")) && !settings.shadow.enabled)
            throw UsageError(QStringLiteral("--depth-out needs shadows; drop --set shadow.enabled=false"));

        HeadlessRenderer headless;
        const QImage scene = headless.renderScene(settings, size);
        out() << formatTexelLine(headless.renderer().lastFrame()) << Qt::endl;
        printFitWarnings(headless.renderer().lastFit());
        if (const QString backend = activeHeadlessBackend(); !backend.isEmpty())
            out() << "headless platform: " << backend << ", " << headless.renderer().rendererString() << Qt::endl;
        QByteArray scenePng, depthPng;
        QSize depthSize;
        if (parser.isSet(QStringLiteral("out")))
            scenePng = encodePng(scene);
        if (parser.isSet(QStringLiteral("depth-out"))) {
            const QImage depth = headless.renderDepthPicture(std::clamp(settings.map.size, 320, 1024));
            depthSize = depth.size();
            depthPng = encodePng(depth);
        }
        if (parser.isSet(QStringLiteral("out"))) {
            writeOutputFile(scenePath, scenePng);
            report(scenePath, scene.size());
        }
        if (parser.isSet(QStringLiteral("depth-out"))) {
            writeOutputFile(depthPath, depthPng);
            report(depthPath, depthSize);
        }
        return kExitOk;
    });
}

} // namespace shadowlab::cli
