#include "CliSupport.h"
#include "Commands.h"
#include "FrameStatsText.h"
#include "FrameTimeHistory.h"
#include "HeadlessRenderer.h"
#include "Measurement.h"
#include "SampleStats.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"
#include "SettingsSummary.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"
#include "TutorialAnchor.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <numeric>
#include <memory>
#include <optional>

namespace shadowlab::cli {

namespace {

// As render: the frame's colour, depth and the shadow map, about 16 bytes per pixel.
const SizeLimits kBenchSize{{1, 1}, {8192, 8192}, QStringLiteral("bench keeps about 16 bytes per pixel in memory")};

struct Phase {
    QString name;
    QString description;
    Settings settings;
    bool moving = false;    // re-render the shadow map every frame, as with a moving light
    std::vector<CameraSettings> cameraPath;     // a moving camera (empty: still)
    double timeStep = 0.0;  // the scene playing: seconds of scene.time a frame (0: still)
    std::unique_ptr<HeadlessRenderer> headless;
    std::vector<double> shadow, lit, shadowWall, litWall, wall;
    std::vector<double> blurWall;
    std::vector<double> outsideWall;
    int shadowPassesRun = 0;
    int shadowMapClears = 0;
    int shadowDraws = 0;
    std::vector<double> pagesDrawn, pagesResident;  // shadow.virtual, every frame
    FrameStats last;
    FittedLight fit;        // of the last frame
    std::vector<std::vector<double>> viewWall;  // cascades or cube faces: wall ms of the frames that drew each
    std::vector<int> viewPassesRun;
    std::vector<int> viewDraws;
    FrameCounts counts;     // one shadow and one lit pass, counted apart from the timed frames
    bool anchor = false;    // the tutorial's own program (TutorialAnchor), not ShadowLab: frame times only
};

// Each phase on its own context, timed by the one interleaved loop so a slow spell of a
// shared machine hits every phase alike and their ratio stays fair.
// The tutorial's program, when asked for, draws one frame after each round of the others, on
// its own context, seen by the first phase's camera.
void runInterleaved(std::vector<Phase>& phases, QSize size, int warmup, int frames)
{
    std::vector<TimedRun> runs;
    std::vector<Phase*> timed;
    Phase* anchorPhase = nullptr;
    for (Phase& p : phases) {
        if (p.anchor) {
            anchorPhase = &p;
            continue;
        }
        runs.push_back({p.headless.get(), p.settings, p.moving, false, {}, p.cameraPath, p.timeStep});
        timed.push_back(&p);
    }
    std::unique_ptr<TutorialAnchor> anchor;
    if (anchorPhase) {
        anchorPhase->headless->makeCurrent();
        anchor = std::make_unique<TutorialAnchor>(anchorPhase->headless->functions(), size);
    }
    // A bar with the time left on a terminal (stderr), nothing in a pipe.
    ProgressBar progress;
    int round = 0;
    timeInterleaved(runs, size, warmup, frames, [&](double f) {
        if (anchor) {
            const CameraFrame camera = timed.front()->headless->renderer().cameraFrame();
            anchorPhase->headless->makeCurrent();
            const double ms = anchor->timedFrame(camera);
            if (round >= warmup)
                anchorPhase->wall.push_back(ms);
        }
        ++round;
        progress.show(f, QStringLiteral("timing"));
    });
    progress.done();
    for (std::size_t i = 0; i < timed.size(); ++i) {
        Phase& p = *timed[i];
        FrameSamples& s = runs[i].samples;
        p.shadow = std::move(s.shadow);
        p.lit = std::move(s.lit);
        p.shadowWall = std::move(s.shadowWall);
        p.litWall = std::move(s.litWall);
        p.blurWall = std::move(s.blurWall);
        p.wall = std::move(s.wall);
        p.outsideWall = std::move(s.outsideWall);
        p.shadowPassesRun = s.shadowPassesRun;
        p.shadowMapClears = s.shadowMapClears;
        p.shadowDraws = s.shadowDraws;
        p.pagesDrawn = std::move(s.pagesDrawn);
        p.pagesResident = std::move(s.pagesResident);
        p.last = s.last;
        p.fit = p.headless->renderer().lastFit();
        p.viewWall = std::move(s.viewWall);
        p.viewPassesRun = std::move(s.viewPassesRun);
        p.viewDraws = std::move(s.viewDraws);
        p.counts = s.counts;
    }
}

// One row of the timing table: a label, then median, p10, p90 and mean in aligned columns.
constexpr int kLabelWidth = 26;
constexpr int kNumberWidth = 10;

QString statsRow(const QString& label, const SampleStats& s)
{
    QString row = QStringLiteral("  ") + label.leftJustified(kLabelWidth);
    if (s.count == 0)
        return row + QStringLiteral("—").rightJustified(kNumberWidth);
    for (double v : {s.median, s.p10, s.p90, s.mean})
        row += QString::number(v, 'f', 2).rightJustified(kNumberWidth);
    return row;
}

QString statsHeader()
{
    QString header = QStringLiteral("  ") + QStringLiteral("ms per frame").leftJustified(kLabelWidth);
    for (const char* column : {"median", "p10", "p90", "mean"})
        header += QString::fromLatin1(column).rightJustified(kNumberWidth);
    return header;
}

QJsonObject statsJson(const SampleStats& s)
{
    return {{QStringLiteral("count"), s.count}, {QStringLiteral("median_ms"), s.median}, {QStringLiteral("p10_ms"), s.p10},
            {QStringLiteral("p90_ms"), s.p90},   {QStringLiteral("min_ms"), s.min},       {QStringLiteral("max_ms"), s.max},
            {QStringLiteral("mean_ms"), s.mean}};
}

// The same for counts (pages a frame): no unit in the names.
QJsonObject countsJson(const SampleStats& s)
{
    return {{QStringLiteral("count"), s.count}, {QStringLiteral("median"), s.median}, {QStringLiteral("p10"), s.p10},
            {QStringLiteral("p90"), s.p90},     {QStringLiteral("min"), s.min},       {QStringLiteral("max"), s.max}};
}

// Per cascade or cube face: how often it was drawn and its wall time when it was.
QJsonArray viewsJson(const Phase& p)
{
    QJsonArray views;
    for (std::size_t v = 0; v < p.viewWall.size(); ++v)
        views.append(QJsonObject{{QStringLiteral("passes_run"), p.viewPassesRun[v]},
                                 {QStringLiteral("draws"), p.viewDraws[v]},
                                 {QStringLiteral("wall"), statsJson(summarize(p.viewWall[v]))}});
    return views;
}

void addBenchOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QStringLiteral("Time the shadow pass, the lit pass and the whole frame (median and spread)."));
    parser.addHelpOption();
    addSettingsOptions(parser);
    parser.addOption({QStringLiteral("size"), QStringLiteral("Frame size (default 1280x720)."), QStringLiteral("WxH"),
                      QStringLiteral("1280x720")});
    parser.addOption({QStringLiteral("frames"), QStringLiteral("Measured frames per phase (default 200)."), QStringLiteral("n"),
                      QStringLiteral("200")});
    parser.addOption({QStringLiteral("warmup"), QStringLiteral("Unmeasured frames first (default 10)."), QStringLiteral("n"),
                      QStringLiteral("10")});
    parser.addOption({QStringLiteral("phase"), QStringLiteral("steady, moving-camera (the scene's camera path, light fitted to it every frame; with and without "
                                     "shadows), moving-light, moving-casters (the scene playing at 60 frames a second of scene time: "
                                     "its moving objects' views redrawn), both (steady and moving-light) or all (default all; "
                                     "moving-casters where the scene moves)."),
                      QStringLiteral("name"), QStringLiteral("all")});
    parser.addOption({QStringLiteral("baseline"),
                      QStringLiteral("Also time a typical tutorial configuration of the same scene (pcf 3x3, 1024 map, shadow pass every frame).")});
    parser.addOption({QStringLiteral("anchor"),
                      QStringLiteral("Also time the LearnOpenGL 3.1.3 tutorial's own frame: a plain OpenGL program of its scene, shaders and "
                                     "state (pcf 3x3 of nine reads, a 1024 map drawn every frame, glFinish as its swap), none of "
                                     "ShadowLab's code, seen by the same camera at the same size; ratios are then to it.")});
    parser.addOption({QStringLiteral("without-shadows"),
                      QStringLiteral("Also time the still frame with shadow.enabled=false, interleaved with it frame by frame, and print "
                                     "the lit pass with shadows over without: what the shadow term costs, with its noise.")});
    parser.addOption({QStringLiteral("json"), QStringLiteral("Print JSON for machines.")});
}

// What the command line asks for, checked, with the scene it names loaded once.
struct BenchRequest {
    Settings settings;
    double loadMs = 0.0;            // importing a model or scene file, then checking it
    std::size_t triangles = 0;
    std::size_t objects = 0;
    QSize size;
    int frames = 0;
    int warmup = 0;
    QString phase;
    bool baseline = false;          // also the tutorial's configuration
    bool anchor = false;            // also the tutorial's own program
    bool withoutShadows = false;    // also the still frame without shadows
    bool moves = false;             // the scene has moving objects
};

bool wantsSteady(const BenchRequest& r)
{
    return r.phase == u"all" || r.phase == u"both" || r.phase == u"steady";
}

bool wantsMovingCasters(const BenchRequest& r)
{
    return r.phase == u"moving-casters" || (r.phase == u"all" && r.moves);
}

bool wantsMovingCamera(const BenchRequest& r)
{
    return r.phase == u"all" || r.phase == u"moving-camera";
}

BenchRequest readBenchRequest(const QCommandLineParser& parser)
{
    BenchRequest r;
    // A model or scene file is imported here (then cached), so this is its load time.
    QElapsedTimer loadTimer;
    loadTimer.start();
    r.settings = settingsFromOptions(parser);
    r.loadMs = double(loadTimer.nsecsElapsed()) * 1e-6;
    const Scene scene = buildScene(r.settings.scene);
    for (const SceneObject& object : scene.objects)
        r.triangles += scene.meshes.at(std::size_t(object.mesh)).indices.size() / 3;
    r.objects = scene.objects.size();
    r.moves = scene.moves();
    r.size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kBenchSize);
    r.frames = parseCount(parser.value(QStringLiteral("frames")), QStringLiteral("frames"), 1, 100000);
    r.warmup = parseCount(parser.value(QStringLiteral("warmup")), QStringLiteral("warmup"), 0, 10000);
    r.phase = parser.value(QStringLiteral("phase"));
    if (r.phase != u"both" && r.phase != u"all" && r.phase != u"steady" && r.phase != u"moving-light" && r.phase != u"moving-camera"
        && r.phase != u"moving-casters")
        throw UsageError(QStringLiteral("--phase: '%1' is not a phase; choose steady, moving-camera, moving-light, moving-casters, both or all").arg(r.phase));
    if (r.phase == u"moving-casters" && !r.moves)
        throw UsageError(QStringLiteral("--phase moving-casters: nothing in the scene %1 moves; choose a scene that does, e.g. --scene swing or "
                                        "--scene city+50").arg(displayText(r.settings.scene)));
    r.baseline = parser.isSet(QStringLiteral("baseline"));
    r.anchor = parser.isSet(QStringLiteral("anchor"));
    r.withoutShadows = parser.isSet(QStringLiteral("without-shadows"));
    if (r.withoutShadows && !wantsSteady(r))
        throw UsageError(QStringLiteral("--without-shadows: it times the still frame without shadows against the steady phase; use "
                                        "--phase steady, both or all"));
    if (r.anchor && r.settings.scene != u"seed")
        throw UsageError(QStringLiteral("--anchor: the tutorial's program draws its own scene, which is seed's; use --scene seed or leave --anchor out"));
    return r;
}

// The phases `--phase` names, each with its own renderer, and the tutorial's after them.
std::vector<Phase> makePhases(const BenchRequest& r)
{
    std::vector<Phase> phases;
    auto addPhase = [&](const char* name, const char* description, const Settings& s, bool moving) {
        Phase p;
        p.name = QString::fromLatin1(name);
        p.description = QString::fromLatin1(description);
        p.settings = s;
        p.moving = moving;
        p.headless = std::make_unique<HeadlessRenderer>();
        phases.push_back(std::move(p));
    };
    const bool all = r.phase == u"all";
    if (wantsSteady(r))
        addPhase("steady", "light and camera still: cached shadow map, lit pass only", r.settings, false);
    if (r.withoutShadows) {
        Settings withoutShadows = r.settings;
        withoutShadows.shadow.enabled = false;
        addPhase("steady-no-shadows", "the same still frame with shadow.enabled=false", withoutShadows, false);
    }
    if (all || r.phase == u"both" || r.phase == u"moving-light")
        addPhase("moving-light", "shadow pass every frame", r.settings, true);
    if (wantsMovingCamera(r)) {
        // A walk of 0.05 world units per frame: maps (cascades) are redrawn only when their
        // fitted volume changes. The same walk without shadows gives their cost as one ratio.
        addPhase("moving-camera", "camera walking 0.05 units a frame, maps refitted and redrawn when they change", r.settings, false);
        phases.back().cameraPath = cameraPath(r.settings.camera, 64, 0.05);
        Settings withoutShadows = r.settings;
        withoutShadows.shadow.enabled = false;
        addPhase("moving-camera-no-shadows", "the same camera walk with shadow.enabled=false", withoutShadows, false);
        phases.back().cameraPath = cameraPath(r.settings.camera, 64, 0.05);
    }
    if (wantsMovingCasters(r)) {
        addPhase("moving-casters", "the scene playing, 1/60 s of scene.time a frame: the views its moving objects cross redrawn", r.settings, false);
        phases.back().timeStep = 1.0 / 60.0;
        // A cache is timed against drawing every caster (its shadow pass), and against the
        // casters standing still (its whole frame), interleaved with it.
        if (r.settings.shadow.cache != ShadowCachePolicy::Off) {
            Settings uncached = r.settings;
            uncached.shadow.cache = ShadowCachePolicy::Off;
            addPhase("moving-casters-uncached", "the same with shadow.cache=off: every caster of a view drawn again", uncached, false);
            phases.back().timeStep = 1.0 / 60.0;
            addPhase("casters-standing", "the same frame with the clock stopped: casters standing, map kept", r.settings, false);
        }
    }
    if (r.baseline)
        addPhase("tutorial-baseline", "pcf 3x3, 1024 map, bias max(0.05 (1 - N.L), 0.005), shadow pass every frame",
                 tutorialSettings(r.settings), true);
    if (r.anchor) {
        addPhase("tutorial-program", "the LearnOpenGL 3.1.3 program's own frame: plain OpenGL, pcf 3x3, 1024 map every frame, glFinish as its swap",
                 r.settings, true);
        phases.back().anchor = true;
    }
    return phases;
}

QString configurationSummary(const BenchRequest& r)
{
    const Settings& settings = r.settings;
    // The map as laid out ("2048² ortho", "4 cascades of 2048²", "virtual map of 900 pages of 128²").
    return QStringLiteral("scene %1, %2x%3, map: %4 %5, filter %6, bias slope %7 min %8")
        .arg(settings.scene)
        .arg(r.size.width())
        .arg(r.size.height())
        .arg(mapLayoutSummary(settings), toString(settings.map.format), filterLabel(settings.filter))
        .arg(settings.bias.slope)
        .arg(settings.bias.min);
}

// `gpuTimed`: the renderer ran its timer queries (not on a software one): else the GPU rows are null.
QJsonObject phaseJson(const Phase& r, int frames, bool gpuTimed)
{
    const auto gpu = [gpuTimed](const std::vector<double>& ms) { return gpuTimed ? QJsonValue(statsJson(summarize(ms))) : QJsonValue(); };
    return {{QStringLiteral("phase"), r.name},
            {QStringLiteral("description"), r.description},
            {QStringLiteral("frames"), frames},
            {QStringLiteral("shadow_passes_run"), r.shadowPassesRun},
            {QStringLiteral("shadow_pass_cached"), r.shadowPassesRun == 0},
            {QStringLiteral("shadow_map_clears"), r.shadowMapClears},
            {QStringLiteral("shadow_draws"), r.shadowDraws},
            {QStringLiteral("virtual_pages_drawn"), countsJson(summarize(r.pagesDrawn))},
            {QStringLiteral("virtual_pages_resident"), countsJson(summarize(r.pagesResident))},
            {QStringLiteral("texel_world_size_as_set"), r.last.texelWorldSizeBeforeFit},
            {QStringLiteral("texel_world_size"), r.last.texelWorldSize},
            {QStringLiteral("shadow_pass_gpu"), gpu(r.shadow)},
            {QStringLiteral("lit_pass_gpu"), gpu(r.lit)},
            {QStringLiteral("shadow_pass_wall"), statsJson(summarize(r.shadowWall))},
            {QStringLiteral("lit_pass_wall"), statsJson(summarize(r.litWall))},
            {QStringLiteral("blur_wall"), statsJson(summarize(r.blurWall))},
            {QStringLiteral("frame_wall"), statsJson(summarize(r.wall))},
            {QStringLiteral("outside_passes_wall"), statsJson(summarize(r.outsideWall))},
            {QStringLiteral("views"), viewsJson(r)},
            {QStringLiteral("counts"), countsJson(r.counts)}};
}

// Each round's frame of `r` over the same round's frame of `reference`. The loop times one
// frame of every phase a round, so a slow spell of a shared machine moves both sides of a
// round's ratio alike: their spread is the noise of the ratio itself, which the two phases'
// own spreads overstate.
SampleStats roundRatios(const Phase& r, const Phase& reference, std::vector<double> Phase::*times = &Phase::wall)
{
    const std::vector<double>& a = r.*times;
    const std::vector<double>& b = reference.*times;
    std::vector<double> ratios;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        if (b[k] > 0.0)
            ratios.push_back(a[k] / b[k]);
    }
    return summarize(std::move(ratios));
}

const Phase* findPhase(const std::vector<Phase>& phases, const char* name)
{
    const auto found = std::find_if(phases.begin(), phases.end(), [name](const Phase& p) { return p.name == QLatin1String(name); });
    return found == phases.end() ? nullptr : &*found;
}

// The still lit pass with shadows over without (--without-shadows): the ratio of the medians,
// and the p10, median and p90 of the ratios round by round.
struct ShadowCost {
    double ratioOfMedians = 0.0;
    SampleStats rounds;
};

std::optional<ShadowCost> shadowCost(const std::vector<Phase>& phases)
{
    const Phase* on = findPhase(phases, "steady");
    const Phase* off = findPhase(phases, "steady-no-shadows");
    if (!on || !off)
        return std::nullopt;
    return ShadowCost{summarize(on->litWall).median / summarize(off->litWall).median, roundRatios(*on, *off, &Phase::litWall)};
}

// shadow.cache with casters moving, round by round: its shadow pass over the same frames with
// shadow.cache=off, and its frame over the casters standing still.
// The shadow pass per frame is its time summed over the frames it ran in, over all frames (a
// cache may leave it out of some).
struct CacheGain {
    double shadowPassPerFrame = 0.0;    // cached over uncached
    double shadowPassMedian = 0.0;      // ... of the frames it ran in
    SampleStats frame;
};

std::optional<CacheGain> cacheGain(const std::vector<Phase>& phases)
{
    const Phase* cached = findPhase(phases, "moving-casters");
    const Phase* uncached = findPhase(phases, "moving-casters-uncached");
    const Phase* standing = findPhase(phases, "casters-standing");
    if (!cached || !uncached || !standing)
        return std::nullopt;
    const auto perFrame = [](const Phase& p) { return std::accumulate(p.shadowWall.begin(), p.shadowWall.end(), 0.0) / std::max<std::size_t>(p.wall.size(), 1); };
    return CacheGain{perFrame(*cached) / std::max(perFrame(*uncached), 1e-9),
                     summarize(cached->shadowWall).median / std::max(summarize(uncached->shadowWall).median, 1e-9), roundRatios(*cached, *standing)};
}

void printJson(const BenchRequest& request, const std::vector<Phase>& phases, const QString& rendererString)
{
    QJsonArray phaseArray;
    for (const Phase& r : phases) {
        QJsonObject phase = phaseJson(r, request.frames, !isSoftwareRenderer(rendererString));
        if (phases.size() > 1) {
            const SampleStats rounds = roundRatios(r, phases.back());
            phase.insert(QStringLiteral("frame_wall_relative"),
                         QJsonObject{{QStringLiteral("to"), phases.back().name},
                                     {QStringLiteral("ratio_of_medians"), summarize(r.wall).median / summarize(phases.back().wall).median},
                                     {QStringLiteral("ratio_of_means"), summarize(r.wall).mean / summarize(phases.back().wall).mean},
                                     {QStringLiteral("rounds"), rounds.count},
                                     {QStringLiteral("round_median"), rounds.median},
                                     {QStringLiteral("round_p10"), rounds.p10},
                                     {QStringLiteral("round_p90"), rounds.p90}});
        }
        phaseArray.append(phase);
    }
    QJsonObject document{{QStringLiteral("renderer"), rendererString},
                         {QStringLiteral("gpu_timer_meaningful"), !isSoftwareRenderer(rendererString)},
                         {QStringLiteral("rasteriser_profile"), profileName(RasteriserTuning::of(request.settings.rasteriser.profile, rendererString))},
                         {QStringLiteral("configuration"), configurationSummary(request)},
                         {QStringLiteral("scene_load_ms"), request.loadMs},
                         {QStringLiteral("triangles"), qint64(request.triangles)},
                         {QStringLiteral("objects"), qint64(request.objects)},
                         {QStringLiteral("settings"), settingsToJson(request.settings)},
                         {QStringLiteral("phases"), phaseArray}};
    if (const std::optional<ShadowCost> cost = shadowCost(phases))
        document.insert(QStringLiteral("still_lit_pass_shadows_over_none"),
                        QJsonObject{{QStringLiteral("ratio_of_medians"), cost->ratioOfMedians},
                                    {QStringLiteral("rounds"), cost->rounds.count},
                                    {QStringLiteral("round_median"), cost->rounds.median},
                                    {QStringLiteral("round_p10"), cost->rounds.p10},
                                    {QStringLiteral("round_p90"), cost->rounds.p90}});
    if (const std::optional<CacheGain> gain = cacheGain(phases)) {
        const auto ratios = [](const SampleStats& s) {
            return QJsonObject{{QStringLiteral("rounds"), s.count}, {QStringLiteral("round_median"), s.median}, {QStringLiteral("round_p10"), s.p10},
                               {QStringLiteral("round_p90"), s.p90}};
        };
        document.insert(QStringLiteral("cache"), QJsonObject{{QStringLiteral("policy"), toString(request.settings.shadow.cache)},
                                                             {QStringLiteral("shadow_pass_per_frame_over_uncached"), gain->shadowPassPerFrame},
                                                             {QStringLiteral("shadow_pass_median_over_uncached"), gain->shadowPassMedian},
                                                             {QStringLiteral("frame_over_standing"), ratios(gain->frame)}});
    }
    out() << QJsonDocument(document).toJson(QJsonDocument::Indented);
}

// One phase's table; a software renderer's "GPU" rows are left out (see printText). The
// tutorial's program is timed as a whole frame only, and a phase without shadows has no
// shadow pass to time or texel to size: their rows would only say something untrue.
void printPhase(const Phase& r, const BenchRequest& request, bool software)
{
    const int frames = request.frames;
    out() << '\n' << r.name << " (" << r.description << "), " << frames << " frames after " << request.warmup << " warm-up\n";
    out() << statsHeader() << '\n';
    if (r.anchor) {
        out() << statsRow(QStringLiteral("frame (wall)"), summarize(r.wall)) << "   (its passes are not timed apart)\n";
        return;
    }
    const bool shadows = r.settings.shadow.enabled;
    const QString runs = QStringLiteral("   run in %1/%2 frames").arg(r.shadowPassesRun).arg(frames)
                         + (r.shadowPassesRun == 0 ? QStringLiteral(" (cached)") : QStringLiteral(", %1 draws").arg(r.shadowDraws))
                         + (r.shadowPassesRun > 0 && r.shadowMapClears < r.shadowPassesRun && slicesDepth(r.settings)
                                ? QStringLiteral(", map cleared in %1 (map.slices=%2)").arg(r.shadowMapClears).arg(r.settings.map.slices)
                                : QString())
                         + (r.settings.shadow.cache != ShadowCachePolicy::Off && r.shadowPassesRun > 0
                                ? QStringLiteral(", shadow.cache=%1").arg(toString(r.settings.shadow.cache))
                                : QString());
    if (!shadows)
        out() << "  " << QStringLiteral("shadow pass").leftJustified(kLabelWidth) << "   none: shadow.enabled=false\n";
    if (shadows && !software)
        out() << statsRow(QStringLiteral("shadow pass (GPU)"), summarize(r.shadow)) << '\n';
    if (shadows)
        out() << statsRow(QStringLiteral("shadow pass (wall)"), summarize(r.shadowWall)) << runs << '\n';
    if (!r.blurWall.empty())
        out() << statsRow(QStringLiteral("  of which blur (wall)"), summarize(r.blurWall)) << "   (moments blur and mips)\n";
    if (!software)
        out() << statsRow(QStringLiteral("lit pass (GPU)"), summarize(r.lit)) << '\n';
    out() << statsRow(QStringLiteral("lit pass (wall)"), summarize(r.litWall)) << '\n';
    out() << statsRow(QStringLiteral("frame (wall)"), summarize(r.wall)) << '\n';
    out() << statsRow(QStringLiteral("  outside the passes"), summarize(r.outsideWall)) << "   (the frame less its shadow and lit passes: the fit, the reach, uploads)\n";
    if (!r.pagesDrawn.empty()) {
        // Counts, not times: apart from the table of milliseconds.
        const SampleStats drawn = summarize(r.pagesDrawn), resident = summarize(r.pagesResident);
        out() << QStringLiteral("  virtual pages a frame: %1 drawn (p10 %2, p90 %3), %4 resident (p10 %5, p90 %6)\n")
                     .arg(drawn.median)
                     .arg(drawn.p10)
                     .arg(drawn.p90)
                     .arg(resident.median)
                     .arg(resident.p10)
                     .arg(resident.p90);
    }
    if (shadows)
        out() << "  " << formatTexelLine(r.last) << '\n';
    // Counts, the same on any GPU: what a reader choosing for one can compare.
    for (const QString& line : countsLines(r.counts))
        out() << "  " << line << '\n';
    for (std::size_t v = 0; v < r.viewWall.size(); ++v) {
        const bool cube = r.settings.light.type == LightType::Point;
        out() << statsRow(QStringLiteral("  %1 %2 (wall)").arg(cube ? QStringLiteral("face") : QStringLiteral("cascade")).arg(v),
                          summarize(r.viewWall[v]))
              << "   drawn in " << r.viewPassesRun[v] << "/" << frames << " frames, " << r.viewDraws[v] << " draws\n";
    }
    printFitWarnings(r.fit, r.name);
}

// Each phase's median frame against the last one's, and shadows on against off on the walk.
void printRatios(const BenchRequest& request, const std::vector<Phase>& phases)
{
    if (phases.size() > 1) {
        const SampleStats reference = summarize(phases.back().wall);
        out() << "\nmedian frame wall time relative to " << phases.back().name << " (and the p10 and p90 of the ratios round by round,\n"
              << "one frame of each a round: the noise of the ratio itself; and the ratio of the means, where a few slow frames count):\n";
        for (const Phase& r : phases) {
            const SampleStats rounds = roundRatios(r, phases.back());
            const SampleStats own = summarize(r.wall);
            out() << "  " << r.name.leftJustified(kLabelWidth) << QString::number(own.median / reference.median, 'f', 2).rightJustified(kNumberWidth);
            if (&r != &phases.back())
                out() << QString::number(rounds.p10, 'f', 2).rightJustified(kNumberWidth) << QString::number(rounds.p90, 'f', 2).rightJustified(kNumberWidth)
                      << QString::number(own.mean / reference.mean, 'f', 2).rightJustified(kNumberWidth);
            out() << '\n';
        }
    }
    if (wantsMovingCamera(request)) {
        const auto median = [&](const char* name) { return summarize(findPhase(phases, name)->wall).median; };
        out() << "median frame wall time, shadows on / off with the camera moving: "
              << QString::number(median("moving-camera") / median("moving-camera-no-shadows"), 'f', 2) << '\n';
    }
    if (const std::optional<CacheGain> gain = cacheGain(phases)) {
        out() << "shadow.cache=" << toString(request.settings.shadow.cache) << ", casters moving: shadow pass / with shadow.cache=off "
              << QString::number(gain->shadowPassPerFrame, 'f', 3) << " a frame (" << QString::number(gain->shadowPassMedian, 'f', 3)
              << " of the medians where it ran); frame / casters standing " << QString::number(gain->frame.median, 'f', 3) << " (round by round, p10 "
              << QString::number(gain->frame.p10, 'f', 3) << ", p90 " << QString::number(gain->frame.p90, 'f', 3) << ")\n";
    }
    if (const std::optional<ShadowCost> cost = shadowCost(phases)) {
        out() << "still lit pass, shadows on / off: " << QString::number(cost->ratioOfMedians, 'f', 3) << " (round by round: median "
              << QString::number(cost->rounds.median, 'f', 3) << ", p10 " << QString::number(cost->rounds.p10, 'f', 3) << ", p90 "
              << QString::number(cost->rounds.p90, 'f', 3) << ")\n";
    }
}

void printText(const BenchRequest& request, const std::vector<Phase>& phases, const QString& rendererString)
{
    out() << "renderer: " << rendererString << '\n' << "configuration: " << configurationSummary(request) << '\n';
    const RasteriserTuning tuning = RasteriserTuning::of(request.settings.rasteriser.profile, rendererString);
    out() << "rasteriser profile: " << profileName(tuning)
          << (tuning.software ? " (a software rasteriser's optimisations on; rasteriser.profile=hardware for the plain path)\n"
                              : " (the plain path; rasteriser.profile=software for a software rasteriser's optimisations)\n");
    // A software renderer's timer queries miss its deferred rasterisation: its "GPU" rows
    // would only mislead, so they are left out and the wall times (CPU time there) stand.
    const bool software = isSoftwareRenderer(rendererString);
    if (software)
        out() << "times: wall clock between glFinish calls, which is CPU time on this software renderer (its GPU timer "
                 "misses the deferred rasterisation, so those rows are left out)\n";
    out() << "scene: " << request.triangles << " triangles in " << request.objects << " drawn objects, loaded and checked in "
          << QString::number(request.loadMs, 'f', 1) << " ms\n";
    for (const Phase& r : phases)
        printPhase(r, request, software);
    printRatios(request, phases);
    out().flush();
}

} // namespace

int runBench(const QStringList& arguments)
{
    return guarded(QStringLiteral("bench"), [&] {
        QCommandLineParser parser;
        addBenchOptions(parser);
        if (!parseArguments(parser, QStringLiteral("bench"), arguments))
            return kExitOk;
        const BenchRequest request = readBenchRequest(parser);
        std::vector<Phase> phases = makePhases(request);
        runInterleaved(phases, request.size, request.warmup, request.frames);
        const QString rendererString = phases.front().headless->renderer().rendererString();
        if (parser.isSet(QStringLiteral("json")))
            printJson(request, phases, rendererString);
        else
            printText(request, phases, rendererString);
        return kExitOk;
    });
}

} // namespace shadowlab::cli
