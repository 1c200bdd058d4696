#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessRenderer.h"
#include "SampleStats.h"
#include "SettingsKeys.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace shadowlab::cli {

namespace {

struct PhaseResult {
    QString name;
    QString description;
    SampleStats shadow;     // GPU ms, frames whose shadow pass ran
    SampleStats lit;        // GPU ms
    SampleStats wall;       // ms, render() to after glFinish
    int frames = 0;
    int shadowPassesRun = 0;
    int shadowDraws = 0;
};

// `moving` re-renders the shadow map every frame, as a renderer without the cache (or with a
// moving light) must; `steady` is a still light and camera, where the cached map is reused.
PhaseResult runPhase(HeadlessRenderer& headless, const Settings& settings, QSize size, int warmup, int frames, bool moving)
{
    PhaseResult r;
    r.name = moving ? QStringLiteral("moving-light") : QStringLiteral("steady");
    r.description = moving ? QStringLiteral("shadow pass every frame") : QStringLiteral("shadow map cached, lit pass only");
    std::vector<double> shadow, lit, wall;
    for (int i = 0; i < warmup + frames; ++i) {
        if (moving)
            headless.renderer().invalidateShadowMap();
        headless.renderFrame(settings, size, TimingMode::Finish);
        if (i < warmup)
            continue;
        const FrameStats& f = headless.renderer().lastFrame();
        if (f.shadowPassRendered) {
            shadow.push_back(f.shadowPassMs);
            ++r.shadowPassesRun;
            r.shadowDraws = f.shadowDraws;
        }
        lit.push_back(f.litPassMs);
        wall.push_back(f.frameWallMs);
    }
    r.frames = frames;
    r.shadow = summarize(shadow);
    r.lit = summarize(lit);
    r.wall = summarize(wall);
    return r;
}

QString formatStats(const SampleStats& s)
{
    if (s.count == 0)
        return QStringLiteral("—");
    return QStringLiteral("%1 ms  [p10 %2, p90 %3]").arg(s.median, 0, 'f', 2).arg(s.p10, 0, 'f', 2).arg(s.p90, 0, 'f', 2);
}

QJsonObject statsJson(const SampleStats& s)
{
    return {{QStringLiteral("count"), s.count}, {QStringLiteral("median_ms"), s.median}, {QStringLiteral("p10_ms"), s.p10},
            {QStringLiteral("p90_ms"), s.p90},   {QStringLiteral("min_ms"), s.min},       {QStringLiteral("max_ms"), s.max}};
}

} // namespace

int runBench(const QStringList& arguments)
{
    return guarded(QStringLiteral("bench"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("Time the shadow pass, the lit pass and the whole frame (median and spread)."));
        parser.addHelpOption();
        addSettingsOptions(parser);
        parser.addOption({QStringLiteral("size"), QStringLiteral("Frame size (default 1280x720)."), QStringLiteral("WxH"),
                          QStringLiteral("1280x720")});
        parser.addOption({QStringLiteral("frames"), QStringLiteral("Measured frames per phase (default 200)."), QStringLiteral("n"),
                          QStringLiteral("200")});
        parser.addOption({QStringLiteral("warmup"), QStringLiteral("Unmeasured frames first (default 10)."), QStringLiteral("n"),
                          QStringLiteral("10")});
        parser.addOption({QStringLiteral("phase"), QStringLiteral("steady, moving-light or both (default both)."), QStringLiteral("name"),
                          QStringLiteral("both")});
        parser.addOption({QStringLiteral("json"), QStringLiteral("Print JSON for machines.")});
        if (!parser.parse(QStringList{QStringLiteral("shadowlab bench")} + arguments))
            throw UsageError(parser.errorText());
        if (parser.isSet(QStringLiteral("help"))) {
            out() << parser.helpText();
            return kExitOk;
        }
        const Settings settings = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"));
        const int frames = parseCount(parser.value(QStringLiteral("frames")), QStringLiteral("frames"), 1, 100000);
        const int warmup = parseCount(parser.value(QStringLiteral("warmup")), QStringLiteral("warmup"), 0, 10000);
        const QString phase = parser.value(QStringLiteral("phase"));
        if (phase != u"both" && phase != u"steady" && phase != u"moving-light")
            throw UsageError(QStringLiteral("--phase: '%1' is not a phase; choose steady, moving-light or both").arg(phase));

        HeadlessRenderer headless;
        std::vector<PhaseResult> results;
        if (phase != u"moving-light")
            results.push_back(runPhase(headless, settings, size, warmup, frames, false));
        if (phase != u"steady")
            results.push_back(runPhase(headless, settings, size, warmup, frames, true));

        const QString rendererString = headless.renderer().rendererString();
        const QString filter = settings.filter.mode == FilterMode::Pcf
                                   ? QStringLiteral("pcf %1x%1").arg(settings.filter.kernel)
                                   : toString(settings.filter.mode);
        const QString summary = QStringLiteral("scene %1, %2x%3, map %4x%4 %5, filter %6, bias slope %7 min %8")
                                    .arg(settings.scene)
                                    .arg(size.width())
                                    .arg(size.height())
                                    .arg(settings.map.size)
                                    .arg(toString(settings.map.format), filter)
                                    .arg(settings.bias.slope)
                                    .arg(settings.bias.min);
        if (parser.isSet(QStringLiteral("json"))) {
            QJsonArray phases;
            for (const PhaseResult& r : results) {
                phases.append(QJsonObject{{QStringLiteral("phase"), r.name},
                                          {QStringLiteral("frames"), r.frames},
                                          {QStringLiteral("shadow_passes_run"), r.shadowPassesRun},
                                          {QStringLiteral("shadow_pass_cached"), r.shadowPassesRun == 0},
                                          {QStringLiteral("shadow_draws"), r.shadowDraws},
                                          {QStringLiteral("shadow_pass_gpu"), statsJson(r.shadow)},
                                          {QStringLiteral("lit_pass_gpu"), statsJson(r.lit)},
                                          {QStringLiteral("frame_wall"), statsJson(r.wall)}});
            }
            out() << QJsonDocument(QJsonObject{{QStringLiteral("renderer"), rendererString},
                                               {QStringLiteral("configuration"), summary},
                                               {QStringLiteral("settings"), settingsToJson(settings)},
                                               {QStringLiteral("phases"), phases}})
                         .toJson(QJsonDocument::Indented);
            return kExitOk;
        }
        out() << "renderer: " << rendererString << '\n' << "configuration: " << summary << '\n';
        for (const PhaseResult& r : results) {
            out() << '\n' << r.name << " (" << r.description << "), " << r.frames << " frames after " << warmup << " warm-up\n";
            out() << "  shadow pass (GPU): " << formatStats(r.shadow) << "   run in " << r.shadowPassesRun << "/" << r.frames
                  << " frames" << (r.shadowPassesRun == 0 ? " (cached)" : QString()) << '\n';
            out() << "  lit pass (GPU):    " << formatStats(r.lit) << '\n';
            out() << "  frame (wall):      " << formatStats(r.wall) << '\n';
        }
        out().flush();
        return kExitOk;
    });
}

} // namespace shadowlab::cli
