#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessRenderer.h"
#include "IoError.h"
#include "RenderError.h"

#include <QFileInfo>

namespace shadowlab::cli {

namespace {

void save(const QImage& image, const QString& path)
{
    if (!image.save(path, "PNG"))
        throw IoError(QStringLiteral("cannot write '%1'; check that its folder exists and is writable").arg(path));
    out() << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << image.width() << "x" << image.height() << ")" << Qt::endl;
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
        parser.addOption({QStringLiteral("depth-out"), QStringLiteral("PNG of the light's shadow map."), QStringLiteral("file.png")});
        if (!parseArguments(parser, QStringLiteral("render"), arguments))
            return kExitOk;
        if (!parser.isSet(QStringLiteral("out")) && !parser.isSet(QStringLiteral("depth-out")))
            throw UsageError(QStringLiteral("say where to write: --out scene.png and/or --depth-out depth.png"));

        const Settings settings = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"));

        HeadlessRenderer headless;
        const QImage scene = headless.renderScene(settings, size);
        out() << formatTexelLine(headless.renderer().lastFrame()) << Qt::endl;
        printFitWarnings(headless.renderer().lastFit());
        if (parser.isSet(QStringLiteral("out")))
            save(scene, parser.value(QStringLiteral("out")));
        if (parser.isSet(QStringLiteral("depth-out"))) {
            if (!settings.shadow.enabled)
                throw UsageError(QStringLiteral("--depth-out needs shadows; drop --set shadow.enabled=false"));
            const int side = std::min(settings.map.size, 2048);
            save(headless.renderDepthMap(QSize(side, side)), parser.value(QStringLiteral("depth-out")));
        }
        return kExitOk;
    });
}

} // namespace shadowlab::cli
