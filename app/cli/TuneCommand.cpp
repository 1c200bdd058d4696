#include "BiasTuner.h"
#include "CliSupport.h"
#include "Commands.h"
#include "HeadlessRenderer.h"
#include "OutputFile.h"
#include "SettingsKeys.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace shadowlab::cli {

namespace {

// Each candidate at each placement renders and traces the image once; the reference per
// placement is kept, about 90 bytes per pixel as in `report`.
const SizeLimits kTuneSize{{1, 1}, {1920, 1080}, QStringLiteral("tune renders every candidate at every light direction at this size")};

QString percent(double share) { return QString::number(100.0 * share, 'f', 3); }

QJsonObject candidateJson(const BiasCandidate& c)
{
    return {{QStringLiteral("slope"), c.slope}, {QStringLiteral("min"), c.min}, {QStringLiteral("false_shadow"), c.falseShadow},
            {QStringLiteral("false_light"), c.falseLight}, {QStringLiteral("misclassified"), c.misclassified()}};
}

} // namespace

int runTune(const QStringList& arguments)
{
    return guarded(QStringLiteral("tune"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral(
            "Search the bias (bias.slope x bias.min, in the unit of bias.space) that misclassifies the fewest pixels against the "
            "ray-traced hard reference, over the current view and a spread of light directions; print the acne-against-leak "
            "trade-off and the best setting."));
        parser.addHelpOption();
        addSettingsOptions(parser);
        parser.addOption({QStringLiteral("size"), QStringLiteral("Image size measured (default 320x180)."), QStringLiteral("WxH"),
                          QStringLiteral("320x180")});
        parser.addOption({QStringLiteral("out"), QStringLiteral("Write the settings with the best bias to this JSON file."),
                          QStringLiteral("file.json")});
        parser.addOption({QStringLiteral("json"), QStringLiteral("Print JSON for machines.")});
        if (!parseArguments(parser, QStringLiteral("tune"), arguments))
            return kExitOk;
        const Settings settings = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kTuneSize);
        if (parser.isSet(QStringLiteral("out")))
            checkOutputFile(parser.value(QStringLiteral("out")), QStringLiteral("--out"));   // before minutes of work

        HeadlessRenderer headless;
        BiasTuner tuner(settings, size);
        ProgressBar progress;
        while (!tuner.done()) {
            tuner.step(headless.renderer());
            progress.show(double(tuner.stepsDone()) / tuner.steps(), QStringLiteral("tuning bias"));
        }
        progress.done();
        const BiasTuning t = tuner.result();
        const BiasCandidate& best = t.candidates[t.best];
        Settings tuned = settings;
        tuned.bias.slope = best.slope;
        tuned.bias.min = best.min;
        if (parser.isSet(QStringLiteral("out")))
            saveSettingsFile(parser.value(QStringLiteral("out")), tuned);   // whole or not at all

        const QString unit = toString(t.space);
        if (parser.isSet(QStringLiteral("json"))) {
            QJsonArray front, all;
            for (const std::size_t i : t.front)
                front.append(candidateJson(t.candidates[i]));
            for (const BiasCandidate& c : t.candidates)
                all.append(candidateJson(c));
            QJsonArray placements;
            for (const glm::dvec3& p : t.placements)
                placements.append(QJsonArray{p.x, p.y, p.z});
            out() << QJsonDocument(QJsonObject{{QStringLiteral("renderer"), headless.renderer().rendererString()},
                                               {QStringLiteral("bias_space"), unit},
                                               {QStringLiteral("light_placements"), placements},
                                               {QStringLiteral("current"), candidateJson(t.current)},
                                               {QStringLiteral("best"), candidateJson(best)},
                                               {QStringLiteral("front"), front},
                                               {QStringLiteral("candidates"), all}})
                         .toJson(QJsonDocument::Indented);
            return kExitOk;
        }
        out() << "renderer: " << headless.renderer().rendererString() << '\n'
              << "bias in " << unit << " units, " << t.candidates.size() << " settings x " << t.placements.size()
              << " light directions at " << size.width() << "x" << size.height() << ", against the hard reference\n\n"
              << "the trade-off (no other setting has less of both), in % of measured pixels:\n"
              << QStringLiteral("  %1 %2 %3 %4\n").arg(QStringLiteral("slope"), 8).arg(QStringLiteral("min"), 8)
                     .arg(QStringLiteral("false shadow"), 13).arg(QStringLiteral("false light"), 12);
        for (const std::size_t i : t.front) {
            const BiasCandidate& c = t.candidates[i];
            out() << QStringLiteral("  %1 %2 %3 %4%5\n").arg(c.slope, 8).arg(c.min, 8).arg(percent(c.falseShadow), 13)
                         .arg(percent(c.falseLight), 12).arg(i == t.best ? QStringLiteral("   <- best") : QString());
        }
        out() << '\n' << QStringLiteral("current  slope %1, min %2: misclassified %3 % (false shadow %4 %, false light %5 %)\n")
                             .arg(t.current.slope).arg(t.current.min).arg(percent(t.current.misclassified()), percent(t.current.falseShadow),
                                                                          percent(t.current.falseLight))
              << QStringLiteral("best     slope %1, min %2: misclassified %3 % (false shadow %4 %, false light %5 %)\n")
                     .arg(best.slope).arg(best.min).arg(percent(best.misclassified()), percent(best.falseShadow), percent(best.falseLight))
              << "apply with: --set bias.space=" << unit << " --set bias.slope=" << best.slope << " --set bias.min=" << best.min << '\n';
        if (parser.isSet(QStringLiteral("out")))
            out() << "wrote " << QFileInfo(parser.value(QStringLiteral("out"))).absoluteFilePath() << '\n';
        return kExitOk;
    });
}

} // namespace shadowlab::cli
