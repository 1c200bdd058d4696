#include "AccuracyMeter.h"
#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessRenderer.h"
#include "Measurement.h"
#include "OutputFile.h"
#include "ReportSweep.h"
#include "ReportWriter.h"

#include <QDir>
#include <QElapsedTimer>

#include <unistd.h>

namespace shadowlab::cli {

namespace {

// The accuracy pass keeps float targets, world positions and two traced references per pixel,
// about 90 bytes per pixel: 8.3 Mpixels (3840x2160) is about 750 MB.
const SizeLimits kReportSize{{1, 1}, {3840, 2160}, QStringLiteral("report keeps about 90 bytes per pixel in memory")};

} // namespace

int runReport(const QStringList& arguments)
{
    return guarded(QStringLiteral("report"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("Error against run time over a sweep of configurations, "
                                                        "measured against a ray-traced reference of the same pixels."));
        parser.addHelpOption();
        addSettingsOptions(parser);
        parser.addOption({QStringLiteral("size"), QStringLiteral("Image size (default 640x360)."), QStringLiteral("WxH"), QStringLiteral("640x360")});
        parser.addOption({QStringLiteral("sweep"), QStringLiteral("default, filters, resolution, bias, lights, filterable, or a JSON file (default: default)."),
                          QStringLiteral("name|file.json"), QStringLiteral("default")});
        parser.addOption({QStringLiteral("out"), QStringLiteral("Folder for report.csv, report.json and report.html."), QStringLiteral("dir")});
        parser.addOption({QStringLiteral("frames"), QStringLiteral("Timed frames per configuration (default 30)."), QStringLiteral("n"),
                          QStringLiteral("30")});
        parser.addOption({QStringLiteral("warmup"), QStringLiteral("Untimed frames first (default 3)."), QStringLiteral("n"), QStringLiteral("3")});
        parser.addOption({QStringLiteral("area-samples"), QStringLiteral("Area reference samples per axis; n² rays per pixel (default 16)."),
                          QStringLiteral("n"), QStringLiteral("16")});
        if (!parseArguments(parser, QStringLiteral("report"), arguments))
            return kExitOk;
        if (!parser.isSet(QStringLiteral("out")))
            throw UsageError(QStringLiteral("say where to write the report: --out DIR"));
        const QString directory = parser.value(QStringLiteral("out"));
        checkOutputFolder(directory, QStringLiteral("--out")); // before minutes of work, not after
        const Settings base = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kReportSize);
        const int frames = parseCount(parser.value(QStringLiteral("frames")), QStringLiteral("frames"), 1, 10000);
        const int warmup = parseCount(parser.value(QStringLiteral("warmup")), QStringLiteral("warmup"), 0, 1000);
        const int samples = parseCount(parser.value(QStringLiteral("area-samples")), QStringLiteral("area-samples"), 1, 64);
        const std::vector<SweepEntry> sweep = loadSweep(parser.value(QStringLiteral("sweep")));
        std::vector<Settings> configurations;
        for (const SweepEntry& entry : sweep)
            configurations.push_back(applySweepEntry(base, entry)); // every entry is checked before any work starts

        QElapsedTimer total;
        total.start();
        HeadlessRenderer headless;
        AccuracyMeter meter(ReferenceOptions{true, base.reference.lightRadius, samples});
        ProgressBar progress;
        std::vector<ReportRow> rows;
        double raysPerSecond = 0.0, noiseFloor = 0.0;
        // First the accuracy of every configuration (the reference is traced once and reused)...
        const double accuracyShare = 0.5;
        for (std::size_t c = 0; c < sweep.size(); ++c) {
            const double start = accuracyShare * double(c) / sweep.size(), step = accuracyShare / sweep.size();
            ReportRow row{sweep[c].label, sweep[c].assignments, {}, {}, {}, {}, false};
            row.accuracy = measureAccuracy(meter, headless.renderer(), configurations[c], size,
                                         [&](double f) { progress.show(start + step * f, sweep[c].label + QStringLiteral(": accuracy")); });
            printFitWarnings(headless.renderer().lastFit(), sweep[c].label);
            if (row.accuracy.raysPerSecond > 0.0)
                raysPerSecond = row.accuracy.raysPerSecond;
            noiseFloor = std::max(noiseFloor, row.accuracy.areaNoiseFloor);
            rows.push_back(std::move(row));
        }
        // ...then their time, one frame of each in turn, so a slow spell of a shared machine
        // lands on every configuration alike. The shadow pass runs every frame. Each measured
        // frame follows an unmeasured one of the same configuration, so the switch from the
        // previous configuration (a shadow map of another size to allocate) is not timed.
        std::vector<TimedRun> runs;
        for (const Settings& configuration : configurations)
            runs.push_back({&headless, configuration, true, true, {}});
        timeInterleaved(runs, size, warmup, frames,
                        [&](double f) { progress.show(accuracyShare + (1.0 - accuracyShare) * f, QStringLiteral("timing")); });
        for (std::size_t c = 0; c < sweep.size(); ++c) {
            rows[c].shadowPass = summarize(runs[c].samples.shadowWall);
            rows[c].litPass = summarize(runs[c].samples.litWall);
            rows[c].frame = summarize(runs[c].samples.wall);
        }
        progress.done();
        markParetoFront(rows);

        ReportFacts facts;
        facts.scene = base.scene;
        facts.size = size;
        facts.frames = frames;
        facts.warmup = warmup;
        facts.renderer = headless.renderer().rendererString();
        facts.machine = machineFacts();
        facts.areaSamplesPerPixel = samples * samples;
        facts.lightRadius = base.reference.lightRadius;
        facts.areaNoiseFloor = noiseFloor;
        facts.raysPerSecond = raysPerSecond;
        facts.referenceComputations = meter.referenceComputations();
        facts.seconds = double(total.elapsed()) / 1000.0;
        writeReport(directory, rows, facts);

        out() << "configurations: " << rows.size() << ", reference traced " << facts.referenceComputations << " time(s) at "
              << QString::number(raysPerSecond * 1e-6, 'f', 2) << " Mrays/s, " << QString::number(facts.seconds, 'f', 1) << " s in all\n";
        out() << "Pareto front (frame ms, misclassified % against the hard reference):\n";
        for (const ReportRow& r : rows) {
            if (r.paretoFront)
                out() << "  " << r.label.leftJustified(36) << QString::number(r.frame.median, 'f', 2).rightJustified(8) << " ms "
                      << QString::number(100 * r.accuracy.hard.misclassified, 'f', 3).rightJustified(8) << " %\n";
        }
        out() << "wrote " << QDir(directory).absoluteFilePath(QStringLiteral("report.html")) << " (and report.csv, report.json)" << Qt::endl;
        return kExitOk;
    });
}

} // namespace shadowlab::cli
