#include "AccuracyMeter.h"
#include "CliSupport.h"
#include "ErrorNoise.h"
#include "Commands.h"
#include "HeadlessRenderer.h"
#include "Measurement.h"
#include "OutputFile.h"
#include "ReportParts.h"
#include "ReportSweep.h"
#include "ReportWriter.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <numeric>

#include <unistd.h>

namespace shadowlab::cli {

namespace {

// The accuracy pass keeps float targets, world positions, the light terms and two traced
// references per pixel, and the SSIM's local moments for a moment, about 150 bytes per pixel:
// 8.3 Mpixels (3840x2160) is about 1.2 GB.
const SizeLimits kReportSize{{1, 1}, {3840, 2160}, QStringLiteral("report keeps about 150 bytes per pixel in memory")};

// Flicker only where there is some: a column of zeros tells nothing row by row.
void printFlicker(const std::vector<ReportRow>& rows)
{
    const auto flickers = [](const ReportRow& r) { return 100 * std::max(r.flicker.flicker, r.flicker.meanChange) >= 0.0005; };
    const auto flickering = std::count_if(rows.begin(), rows.end(), flickers);
    out() << "flicker (receiver pixels flipping per frame, camera walking " << kFlickerStepTexels << " texel a frame): ";
    if (flickering == 0) {
        out() << "no configuration flickers above 0.0005 %\n";
        return;
    }
    out() << '\n';
    for (const ReportRow& r : rows) {
        if (flickers(r))
            out() << "  " << r.label.leftJustified(36) << QString::number(100 * r.flicker.flicker, 'f', 3).rightJustified(8) << " %\n";
    }
    if (flickering < qsizetype(rows.size()))
        out() << "  the other " << rows.size() - std::size_t(flickering) << " configurations flicker below 0.0005 %\n";
}

constexpr int kLabelWidth = 40;

// Each row's misclassified pixels over the animation's instants: the mean, and the worst with its time.
void printAnimation(const std::vector<ReportRow>& rows)
{
    out() << "over the animation (" << rows.front().animation.times.size() << " instants; misclassified, mean and worst):\n";
    for (const ReportRow& r : rows) {
        const AnimatedError& a = r.animation;
        const std::size_t worst = a.worst();
        out() << "  " << r.label.leftJustified(kLabelWidth) << QString::number(100 * mean(a.misclassified), 'f', 3).rightJustified(8) << " %"
              << QString::number(100 * a.misclassified[worst], 'f', 3).rightJustified(8) << " % at " << QString::number(a.times[worst], 'f', 2) << " s";
        if (r.timeFlicker.measured())
            out() << ", flicker in time " << QString::number(100 * r.timeFlicker.flicker, 'f', 3) << " %";
        out() << '\n';
    }
}

// Each light's fronts, error and cost, fastest first: the choices the report leaves a reader.
void printFronts(const std::vector<ReportRow>& rows)
{
    const QStringList lights = lightsOf(rows);
    const bool area = std::any_of(rows.begin(), rows.end(), [](const ReportRow& r) { return measuredPixels(r, ErrorAxis::AreaMae) > 0; });
    for (const QString& light : lights) {
        const bool time = rows.empty() || isTime(rows.front().costAxis);
        out() << "\nPareto front" << (lights.size() > 1 ? QStringLiteral(" of the %1").arg(light) : QString())
              << (time ? " (off it only when another is clearly faster and clearly more accurate):\n"
                       : " on a count's cost, the same on any GPU (off it only when another is clearly cheaper and clearly more accurate):\n")
              << "  " << QStringLiteral("configuration").leftJustified(kLabelWidth)
              << (time ? QStringLiteral("frame ms (p10-p90)") : QStringLiteral("cost a frame")).rightJustified(24)
              << QStringLiteral("misclassified % (px)").rightJustified(26) << (area ? QStringLiteral("area MAE %").rightJustified(18) : QString())
              << "  front\n";
        std::vector<const ReportRow*> front;
        for (const ReportRow& r : rows) {
            if (lightOf(r, rows) == light && (r.paretoFront || r.areaFront))
                front.push_back(&r);
        }
        std::stable_sort(front.begin(), front.end(), [](const ReportRow* a, const ReportRow* b) { return costOf(*a).median < costOf(*b).median; });
        for (const ReportRow* r : front) {
            const double pixels = errorPixels(*r, ErrorAxis::Misclassified);
            const double areaPixels = std::max(1, measuredPixels(*r, ErrorAxis::AreaMae));
            QStringList which;
            if (r->paretoFront)
                which << QStringLiteral("misclassified");
            if (r->areaFront)
                which << QStringLiteral("area");
            out() << "  " << r->label.leftJustified(kLabelWidth, QLatin1Char(' '), true)
                  << (time ? QStringLiteral("%1 (%2-%3)").arg(r->frame.median, 0, 'f', 2).arg(r->frame.p10, 0, 'f', 2).arg(r->frame.p90, 0, 'f', 2)
                           : costText(*r, costOf(*r).median))
                         .rightJustified(24)
                  << QStringLiteral("%1 (%2 ± %3)").arg(100 * r->accuracy.hard.misclassified, 0, 'f', 4).arg(pixels, 0, 'f', 0)
                         .arg(errorNoisePixels(pixels), 0, 'f', 0).rightJustified(26)
                  << (area ? QStringLiteral("%1 ± %2").arg(100 * r->accuracy.area.mae, 0, 'f', 3)
                                 .arg(100 * errorNoisePixels(errorPixels(*r, ErrorAxis::AreaMae)) / areaPixels, 0, 'f', 3).rightJustified(18)
                           : QString())
                  << "  " << which.join(QStringLiteral(", ")) << '\n';
        }
        for (const ReportRow& r : rows) {
            if (const QString wrong = visiblyWrong(r); lightOf(r, rows) == light && !wrong.isEmpty())
                out() << "  left out: " << r.label << ", " << wrong << '\n';
        }
    }
}

// The summary's last lines: what to pick under each light, why, and what was left out for its picture.
void printRecommendations(const std::vector<ReportRow>& rows)
{
    const QStringList lights = lightsOf(rows);
    for (const QString& light : lights) {
        out() << "\nWhat to pick" << (lights.size() > 1 ? QStringLiteral(" under the %1").arg(light) : QString()) << ":\n";
        const std::vector<Recommendation> picks = recommend(rows, light);
        if (picks.empty())
            out() << "  nothing: no configuration under this light had a pixel facing the light in view\n";
        for (const Recommendation& pick : picks)
            out() << "  " << pick.title() << ": " << pick.row->label << "\n    " << pick.reason() << '\n';
        if (const auto wrong = visiblyWrongRows(rows, light); !wrong.empty() && !picks.empty() && picks.front().kind != Recommendation::Kind::LeastWrong)
            out() << "  never picked, visibly wrong: " << wrong.size() << " configuration" << (wrong.size() == 1 ? "" : "s") << " (listed above as left out)\n";
    }
}

void addReportOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QStringLiteral("Error against run time over a sweep of configurations, "
                                                    "measured against a ray-traced reference of the same pixels."));
    parser.addHelpOption();
    addSettingsOptions(parser);
    parser.addOption({QStringLiteral("size"), QStringLiteral("Image size (default 640x360)."), QStringLiteral("WxH"), QStringLiteral("640x360")});
    parser.addOption({QStringLiteral("sweep"), QStringLiteral("default, filters, resolution, bias (a slope/min grid in texels of the map, depth units, polygon offset, culling), lights, filterable (moment techniques, blur "
                                     "0/3/7, 16/32-bit), penumbra (each wide filter with and without penumbra-only filtering), cascades (1-4 at equal texels, stabilised or not, and sdsm), warp (lispsm against "
                                     "no warp at three light placements, its strength, with cascades), virtual (virtual maps against one map and stabilised cascades of the same memory), around (the settings given, "
                                     "one change at a time, as the accuracy dock sweeps), or a JSON file (default: default)."),
                      QStringLiteral("name|file.json"), QStringLiteral("default")});
    parser.addOption({QStringLiteral("out"), QStringLiteral("Folder for report.csv, report.json and report.html."), QStringLiteral("dir")});
    parser.addOption({QStringLiteral("frames"), QStringLiteral("Timed frames per configuration at most (default 30)."), QStringLiteral("n"),
                      QStringLiteral("30")});
    parser.addOption({QStringLiteral("min-frames"),
                      QStringLiteral("Timed frames per configuration at least; timing stops there once its median and p10-p90 hold "
                                     "from batch to batch (default 8; as many as --frames: always that many)."),
                      QStringLiteral("n"), QStringLiteral("8")});
    parser.addOption({QStringLiteral("warmup"), QStringLiteral("Untimed frames first (default 3)."), QStringLiteral("n"), QStringLiteral("3")});
    parser.addOption({QStringLiteral("area-samples"), QStringLiteral("Area reference samples per axis; n² rays per pixel (default 16)."),
                      QStringLiteral("n"), QStringLiteral("16")});
    parser.addOption({QStringLiteral("flicker-frames"),
                      QStringLiteral("Frames of the sub-texel camera walk flicker is measured over; 0 skips it (default 8)."),
                      QStringLiteral("n"), QString::number(kFlickerFrames)});
    parser.addOption({QStringLiteral("times"),
                      QStringLiteral("Measure every configuration at each of these instants of the scene's animation (seconds of "
                                     "scene.time, comma-separated, e.g. 0,0.5,1.5): each row's error is then its worst instant's, with "
                                     "the mean and every instant in report.json, and its time that of the scene playing."),
                      QStringLiteral("t1,t2,...")});
    parser.addOption({QStringLiteral("animation"),
                      QStringLiteral("As --times, at N instants spread evenly over the scene's clip."), QStringLiteral("n")});
    parser.addOption({QStringLiteral("cost"),
                      QStringLiteral("What the fronts, the picks and the charts weigh a configuration's cost by: time (its frame's wall "
                                     "time on this machine, the default), taps (the shadow lookups' texture reads a frame) or samples "
                                     "(the fragments a shadow pass writes); counts are the same on any GPU."),
                      QStringLiteral("axis"), QStringLiteral("time")});
    parser.addOption({QStringLiteral("shard"),
                      QStringLiteral("Measure share K of N of the sweep (every Nth configuration from the Kth), for another process, "
                                     "machine or scheduler job to measure the rest; put the shares together with --merge."),
                      QStringLiteral("K/N")});
    parser.addOption({QStringLiteral("merge"),
                      QStringLiteral("Measure nothing: put together the reports in the folders given after the options (the shares of "
                                     "one sweep, or reports of it from several machines, side by side) into one report in --out.")});
    parser.addPositionalArgument(QStringLiteral("dir"), QStringLiteral("With --merge: the report folders to put together."), QStringLiteral("[dir...]"));
}

// "K/N" of --shard: 1 <= K <= N <= the configurations there are to share.
std::pair<int, int> parseShard(const QString& text, std::size_t configurations)
{
    const std::optional<std::pair<int, int>> share = parseShare(text);
    if (!share)
        throw UsageError(QStringLiteral("--shard %1: give share K of N as K/N, with 1 <= K <= N, e.g. --shard 2/4").arg(displayText(text)));
    const auto [k, n] = *share;
    if (std::size_t(n) > configurations)
        throw UsageError(QStringLiteral("--shard %1: the sweep has %2 configurations, so it cannot be cut into %3 shares; use at most --shard K/%2")
                             .arg(displayText(text))
                             .arg(configurations)
                             .arg(n));
    return {k, n};
}

// What the command line asks for, all of it checked before any work starts.
struct ReportRequest {
    QString directory;
    Settings base;
    Settings tutorial;          // the base with the tutorial's assignments
    QSize size;
    int frames = 0;
    int minFrames = 0;
    int warmup = 0;
    int samples = 0;            // area reference samples per axis
    int flickerFrames = 0;
    std::vector<SweepConfiguration> sweep;      // what this run measures: the whole sweep, or its share
    std::vector<int> sweepIndex;                // each one's place in the whole sweep
    int configurations = 0;                     // in the whole sweep
    int shard = 1, shards = 1;
    QString fingerprint;                        // of the whole sweep and how it is measured
    CostAxis cost = CostAxis::Time;             // what the fronts weigh (--cost)
    std::vector<double> times;                  // the instants of --times or --animation; empty: base.animation.time alone
};

// The most instants a report measures each configuration at: each one traces a reference.
constexpr int kMaxReportInstants = 64;

// --times or --animation, checked against the scene: instants only where something moves.
std::vector<double> readInstants(const QCommandLineParser& parser, const Settings& base)
{
    const bool times = parser.isSet(QStringLiteral("times")), animation = parser.isSet(QStringLiteral("animation"));
    if (!times && !animation)
        return {};
    const QString option = times ? QStringLiteral("times") : QStringLiteral("animation");
    if (times && animation)
        throw UsageError(QStringLiteral("--times and --animation both say when to measure; give one of them"));
    const Scene scene = buildScene(base.scene);
    if (!scene.moves())
        throw UsageError(QStringLiteral("--%1: nothing in the scene %2 moves, so every instant is the same; choose a scene that moves, "
                                        "e.g. --scene swing or --scene city+50").arg(option, displayText(base.scene)));
    std::vector<double> instants;
    if (animation) {
        const int n = parseCount(parser.value(option), option, 1, kMaxReportInstants);
        for (int i = 0; i < n; ++i)
            instants.push_back(scene.clipLength() * double(i) / n);
        return instants;
    }
    const QStringList parts = parser.value(option).split(QLatin1Char(','));
    if (parts.size() > kMaxReportInstants)
        throw UsageError(QStringLiteral("--times: %1 instants; give at most %2").arg(parts.size()).arg(kMaxReportInstants));
    for (const QString& part : parts) {
        bool ok = false;
        const double t = part.trimmed().toDouble(&ok);
        if (!ok || !(t >= 0.0 && t <= 1e6))
            throw UsageError(QStringLiteral("--times: '%1' is not a time; give seconds in [0, 1e6] separated by commas, e.g. --times 0,0.5,1.5")
                                 .arg(displayText(part)));
        instants.push_back(t);
    }
    return instants;
}

// What a report measures, whoever measures it: the size, the timing and reference options and
// every configuration's settings. Shares and reports of other machines merge only when theirs
// is the same.
QString sweepFingerprint(const ReportRequest& r)
{
    QJsonArray configurations;
    for (const SweepConfiguration& c : r.sweep)
        configurations.append(QJsonObject{{QStringLiteral("label"), c.label}, {QStringLiteral("settings"), settingsToJson(c.settings)}});
    const QJsonObject what{{QStringLiteral("size"), QStringLiteral("%1x%2").arg(r.size.width()).arg(r.size.height())},
                           {QStringLiteral("frames"), r.frames},
                           {QStringLiteral("min_frames"), r.minFrames},
                           {QStringLiteral("warmup"), r.warmup},
                           {QStringLiteral("area_samples"), r.samples},
                           {QStringLiteral("flicker_frames"), r.flickerFrames},
                           {QStringLiteral("times"), [&] {
                                QJsonArray times;
                                for (double t : r.times)
                                    times.append(t);
                                return times;
                            }()},
                           {QStringLiteral("configurations"), configurations}};
    return QString::fromLatin1(QCryptographicHash::hash(QJsonDocument(what).toJson(QJsonDocument::Compact), QCryptographicHash::Sha256).toHex().left(16));
}

ReportRequest readReportRequest(const QCommandLineParser& parser)
{
    if (!parser.isSet(QStringLiteral("out")))
        throw UsageError(QStringLiteral("say where to write the report: --out DIR"));
    ReportRequest r;
    r.directory = parser.value(QStringLiteral("out"));
    checkOutputFolder(r.directory, QStringLiteral("--out")); // before minutes of work, not after
    r.base = settingsFromOptions(parser);
    r.size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kReportSize);
    r.frames = parseCount(parser.value(QStringLiteral("frames")), QStringLiteral("frames"), 1, 10000);
    r.minFrames = std::min(r.frames, parseCount(parser.value(QStringLiteral("min-frames")), QStringLiteral("min-frames"), 1, 10000));
    r.warmup = parseCount(parser.value(QStringLiteral("warmup")), QStringLiteral("warmup"), 0, 1000);
    r.samples = parseCount(parser.value(QStringLiteral("area-samples")), QStringLiteral("area-samples"), 1, 64);
    // Every entry is checked before any work starts; identical configurations are measured once.
    r.sweep = distinctConfigurations(r.base, loadSweep(parser.value(QStringLiteral("sweep")), r.base));
    r.tutorial = applySweepEntry(r.base, {QStringLiteral("tutorial"), tutorialAssignments()});
    r.flickerFrames = parseCount(parser.value(QStringLiteral("flicker-frames")), QStringLiteral("flicker-frames"), 0, 1000);
    const std::optional<CostAxis> cost = costAxisFromKey(parser.value(QStringLiteral("cost")));
    if (!cost)
        throw UsageError(QStringLiteral("--cost: '%1' is not a cost axis; choose time, taps or samples").arg(displayText(parser.value(QStringLiteral("cost")))));
    r.cost = *cost;
    r.times = readInstants(parser, r.base);
    r.configurations = int(r.sweep.size());
    r.fingerprint = sweepFingerprint(r);
    if (parser.isSet(QStringLiteral("shard")))
        std::tie(r.shard, r.shards) = parseShard(parser.value(QStringLiteral("shard")), r.sweep.size());
    // Every Nth from the Kth: neighbours in a sweep differ in cost (map sizes, filters), so each
    // share gets some of each.
    std::vector<SweepConfiguration> share;
    for (int i = 0; i < r.configurations; ++i) {
        if (i % r.shards == r.shard - 1) {
            share.push_back(r.sweep[std::size_t(i)]);
            r.sweepIndex.push_back(i);
        }
    }
    r.sweep = std::move(share);
    return r;
}

// The rows with their accuracy, and what the reference cost.
struct AccuracyPass {
    std::vector<ReportRow> rows;
    double raysPerSecond = 0.0;
    double noiseFloor = 0.0;
};

// The share of the progress bar the accuracy pass takes; timing takes the rest.
constexpr double kAccuracyShare = 0.5;

// The frames a stale cache plays before an instant is measured, at 60 a second: every-n at its
// stalest, its moving casters last drawn n - 1 frames before; on-demand drawn at the first
// instant and never asked again (so nothing here). Exact policies need nothing either.
void playUpTo(HeadlessRenderer& headless, const Settings& at, QSize size)
{
    const int n = at.shadow.cacheInterval;
    if (!at.shadow.enabled || at.shadow.cache != ShadowCachePolicy::EveryN || n <= 1)
        return;
    headless.renderer().invalidateShadowMap();
    for (int k = n - 1; k >= 1; --k) {
        Settings before = at;
        before.animation.time = std::max(0.0, at.animation.time - k / 60.0);
        headless.renderFrame(before, size);
    }
}

// One configuration's accuracy and flicker, shown on the progress bar from `start`, `step` wide.
ReportRow measureRow(const ReportRequest& request, const SweepConfiguration& configuration, HeadlessRenderer& headless,
                     AccuracyMeter& meter, ProgressBar& progress, double start, double step)
{
    ReportRow row;
    row.label = configuration.label;
    row.assignments = configuration.assignments;
    row.light = lightDescription(configuration.settings);
    row.defaults = configuration.settings == request.base;
    row.tutorial = configuration.settings == request.tutorial;
    // Each instant of an animation in turn (the reference traced at each); the row keeps the
    // worst instant's error, picture and density.
    const std::vector<double> instants = request.times.empty() ? std::vector<double>{configuration.settings.animation.time} : request.times;
    // Each row from a map of its own: a cache's copies are not the row's before it.
    headless.renderer().invalidateShadowMap();
    for (std::size_t i = 0; i < instants.size(); ++i) {
        Settings at = configuration.settings;
        at.animation.time = instants[i];
        playUpTo(headless, at, request.size);
        const double from = start + step * double(i) / instants.size(), width = step / instants.size();
        TexelDensity density;
        AccuracyResult result = measureAccuracy(meter, headless.renderer(), at, request.size,
                                                [&](double f) { progress.show(from + width * f, configuration.label + QStringLiteral(": accuracy")); },
                                                &density);
        result.hardHeat = QImage();     // a view's; a sweep of many rows keeps only what the page shows
        if (!request.times.empty()) {
            row.animation.times.push_back(instants[i]);
            row.animation.misclassified.push_back(result.hard.misclassified);
            if (result.area.pixels > 0)
                row.animation.areaMae.push_back(result.area.mae);
            row.animation.dssim.push_back(1.0 - result.ssim);
        }
        if (i == 0 || result.hard.misclassified > row.accuracy.hard.misclassified) {
            row.accuracy = std::move(result);
            row.density = density;
        }
    }
    if (request.flickerFrames > 1) {
        progress.show(start + step, configuration.label + QStringLiteral(": flicker"));
        row.flicker = measureFlicker(headless.renderer(), configuration.settings,
                                     subTexelPath(headless.renderer(), configuration.settings, request.size, request.flickerFrames,
                                                  kFlickerStepTexels),
                                     request.size);
    }
    if (request.flickerFrames > 1 && !request.times.empty()) {
        std::vector<double> walk;
        for (int i = 0; i < request.flickerFrames; ++i)
            walk.push_back(request.times.front() + i / 60.0);
        row.timeFlicker = measureTimeFlicker(headless.renderer(), configuration.settings, walk, request.size);
    }
    printFitWarnings(headless.renderer().lastFit(), configuration.label);
    return row;
}

// First the accuracy of every configuration (the reference is traced once and reused)...
AccuracyPass measureAllAccuracy(const ReportRequest& request, HeadlessRenderer& headless, AccuracyMeter& meter, ProgressBar& progress)
{
    AccuracyPass pass;
    const std::vector<SweepConfiguration>& sweep = request.sweep;
    const QString renderer = headless.renderer().rendererString(), machine = machineFacts();
    for (std::size_t c = 0; c < sweep.size(); ++c) {
        const double start = kAccuracyShare * double(c) / sweep.size(), step = kAccuracyShare / sweep.size();
        ReportRow row = measureRow(request, sweep[c], headless, meter, progress, start, step);
        row.sweepIndex = request.sweepIndex[c];
        row.renderer = renderer;
        row.machine = machine;
        if (row.accuracy.raysPerSecond > 0.0)
            pass.raysPerSecond = row.accuracy.raysPerSecond;
        pass.noiseFloor = std::max(pass.noiseFloor, row.accuracy.areaNoiseFloor);
        pass.rows.push_back(std::move(row));
    }
    return pass;
}

// ...then their time, a batch of frames of each in turn, so a slow spell of a shared machine
// lands on every configuration alike. The shadow pass runs every frame. Each batch follows an
// unmeasured frame of the same configuration, so the switch from the previous configuration
// (a shadow map of another size to allocate) is not timed.
void timeAll(const ReportRequest& request, HeadlessRenderer& headless, ProgressBar& progress, std::vector<ReportRow>& rows)
{
    std::vector<TimedRun> runs;
    // Over an animation, the scene plays from the first instant at 60 frames a second of its
    // time, the light still: what a cache saves is timed (shadow.force_invalidate times a moving sun).
    const double timeStep = request.times.empty() ? 0.0 : 1.0 / 60.0;
    for (const SweepConfiguration& configuration : request.sweep) {
        Settings settings = configuration.settings;
        if (!request.times.empty())
            settings.animation.time = request.times.front();
        runs.push_back({&headless, settings, request.times.empty(), true, {}, {}, timeStep});
    }
    SteadyTiming rule;
    rule.minimum = request.minFrames;
    rule.maximum = request.frames;
    timeUntilSteady(runs, request.size, request.warmup, rule,
                    [&](double f) { progress.show(kAccuracyShare + (1.0 - kAccuracyShare) * f, QStringLiteral("timing")); });
    for (std::size_t c = 0; c < request.sweep.size(); ++c) {
        rows[c].shadowPass = summarize(runs[c].samples.shadowWall);
        const std::vector<double>& passes = runs[c].samples.shadowWall;
        rows[c].shadowPerFrame = std::accumulate(passes.begin(), passes.end(), 0.0) / double(std::max<std::size_t>(runs[c].samples.wall.size(), 1));
        rows[c].litPass = summarize(runs[c].samples.litWall);
        rows[c].frame = summarize(runs[c].samples.wall);
        rows[c].counts = runs[c].samples.counts;
    }
}

ReportFacts reportFacts(const ReportRequest& request, const Renderer& renderer, const AccuracyMeter& meter, const AccuracyPass& accuracy,
                        const QElapsedTimer& total)
{
    ReportFacts facts;
    facts.scene = request.base.scene;
    facts.size = request.size;
    facts.frames = request.frames;
    facts.minFrames = request.minFrames;
    facts.warmup = request.warmup;
    facts.renderer = renderer.rendererString();
    facts.machine = machineFacts();
    facts.areaSamplesPerPixel = request.samples * request.samples;
    facts.lightRadius = request.base.reference.lightRadius;
    facts.areaNoiseFloor = accuracy.noiseFloor;
    facts.raysPerSecond = accuracy.raysPerSecond;
    facts.referenceComputations = meter.referenceComputations();
    facts.seconds = double(total.elapsed()) / 1000.0;
    facts.sweep = request.fingerprint;
    facts.configurations = request.configurations;
    facts.shard = request.shard;
    facts.shards = request.shards;
    return facts;
}

void printSummary(const ReportRequest& request, const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    out() << "configurations: " << rows.size() << ", reference traced " << facts.tracedText() << " at "
          << QString::number(facts.raysPerSecond * 1e-6, 'f', 2) << " Mrays/s, " << QString::number(facts.seconds, 'f', 1) << " s in all\n";
    if (request.flickerFrames > 1)
        printFlicker(rows);
    if (!request.times.empty())
        printAnimation(rows);
    printFronts(rows);
    printRecommendations(rows);
    out() << "wrote " << QDir(request.directory).absoluteFilePath(QStringLiteral("report.html")) << " (and report.csv, report.json)" << Qt::endl;
    if (request.shards > 1)
        out() << "this is share " << request.shard << " of " << request.shards << " (" << rows.size() << " of the sweep's " << request.configurations
              << " configurations): put the shares together with `shadowlab report --merge --out DIR SHARE_DIR...`" << Qt::endl;
}

// report --merge: the reports in the folders given, put together into --out.
int runMerge(const QCommandLineParser& parser, const QStringList& folders)
{
    for (const QString& option : parser.optionNames()) {
        if (option != u"merge" && option != u"out")
            throw UsageError(QStringLiteral("--merge measures nothing, so --%1 does not apply; give only --out and the report folders").arg(displayText(option)));
    }
    if (!parser.isSet(QStringLiteral("out")))
        throw UsageError(QStringLiteral("say where to write the merged report: --out DIR"));
    if (folders.isEmpty())
        throw UsageError(QStringLiteral("give the report folders to merge after the options: report --merge --out DIR SHARE_DIR..."));
    const QString directory = parser.value(QStringLiteral("out"));
    checkOutputFolder(directory, QStringLiteral("--out"));
    // Compared as the file system sees them: "share2/", "./share2" and a link to it are share2.
    const auto samePlace = [](const QString& a, const QString& b) {
        const QFileInfo x(a), y(b);
        return x.exists() && y.exists() ? x.canonicalFilePath() == y.canonicalFilePath()
                                        : QDir::cleanPath(x.absoluteFilePath()) == QDir::cleanPath(y.absoluteFilePath());
    };
    for (const QString& folder : folders) {
        if (samePlace(folder, directory))
            throw UsageError(QStringLiteral("--out %1 is one of the reports being merged; write the merged report to a folder of its own").arg(displayText(directory)));
    }
    try {
        std::vector<ReportPart> parts;
        for (const QString& folder : folders)
            parts.push_back(readReportPart(folder));
        const MergedReport merged = mergeReportParts(parts);
        writeReport(directory, merged.rows, merged.facts);
        out() << "merged " << folders.size() << " reports: " << merged.rows.size() << " rows of the sweep's " << merged.facts.configurations
              << " configurations, measured in " << QString::number(merged.facts.seconds, 'f', 1) << " s in all\n";
        for (const QString& note : merged.notes)
            out() << "note: " << note << '\n';
        printFronts(merged.rows);
        printRecommendations(merged.rows);
        out() << "wrote " << QDir(directory).absoluteFilePath(QStringLiteral("report.html")) << " (and report.csv, report.json)" << Qt::endl;
    } catch (const ReportMergeError& e) {
        throw UsageError(QString::fromStdString(e.what()));
    }
    return kExitOk;
}

} // namespace

int runReport(const QStringList& arguments)
{
    return guarded(QStringLiteral("report"), [&] {
        QCommandLineParser parser;
        addReportOptions(parser);
        // The folders --merge reads are its words of their own (after `--` too).
        const bool merge = arguments.contains(QStringLiteral("--merge"));
        if (!parseArguments(parser, QStringLiteral("report"), arguments, merge))
            return kExitOk;
        if (merge)
            return runMerge(parser, parser.positionalArguments());
        const ReportRequest request = readReportRequest(parser);

        QElapsedTimer total;
        total.start();
        HeadlessRenderer headless;
        AccuracyMeter meter(ReferenceOptions{true, request.base.reference.lightRadius, request.samples});
        meter.keepReferences(request.times.size() + 1);
        ProgressBar progress;
        AccuracyPass accuracy = measureAllAccuracy(request, headless, meter, progress);
        timeAll(request, headless, progress, accuracy.rows);
        progress.done();
        for (ReportRow& row : accuracy.rows)
            row.costAxis = request.cost;
        markParetoFronts(accuracy.rows);

        const ReportFacts facts = reportFacts(request, headless.renderer(), meter, accuracy, total);
        writeReport(request.directory, accuracy.rows, facts);
        printSummary(request, accuracy.rows, facts);
        return kExitOk;
    });
}

} // namespace shadowlab::cli
