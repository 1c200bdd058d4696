#include "BiasTuner.h"
#include "CliSupport.h"
#include "ErrorNoise.h"
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
            {QStringLiteral("false_light"), c.falseLight}, {QStringLiteral("misclassified"), c.misclassified()},
            {QStringLiteral("misclassified_pixels"), c.misclassifiedPixels}};
}

QString pixels(const BiasCandidate& c) { return QString::number(c.misclassifiedPixels, 'f', 0); }

QString measured(const BiasCandidate& c)
{
    return QStringLiteral("slope %1, min %2: misclassified %3 % (%4 px; false shadow %5 %, false light %6 %)")
        .arg(c.slope)
        .arg(c.min)
        .arg(percent(c.misclassified()), pixels(c), percent(c.falseShadow), percent(c.falseLight));
}

void addTuneOptions(QCommandLineParser& parser)
{
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
}

BiasTuning searchBias(Renderer& renderer, const Settings& settings, QSize size)
{
    BiasTuner tuner(settings, size);
    ProgressBar progress;
    while (!tuner.done()) {
        tuner.step(renderer);
        progress.show(double(tuner.stepsDone()) / tuner.steps(), QStringLiteral("tuning bias"));
    }
    progress.done();
    return tuner.result();
}

// A change within the error noise buys nothing: the settings stay as they are.
Settings tunedSettings(Settings settings, const BiasTuning& t)
{
    if (t.improves) {
        settings.bias.slope = t.candidates[t.best].slope;
        settings.bias.min = t.candidates[t.best].min;
    }
    return settings;
}

void printJson(const BiasTuning& t, const QString& rendererString)
{
    QJsonArray front, all;
    for (const std::size_t i : t.front)
        front.append(candidateJson(t.candidates[i]));
    for (const BiasCandidate& c : t.candidates)
        all.append(candidateJson(c));
    QJsonArray placements;
    for (const glm::dvec3& p : t.placements)
        placements.append(QJsonArray{p.x, p.y, p.z});
    out() << QJsonDocument(QJsonObject{{QStringLiteral("renderer"), rendererString},
                                       {QStringLiteral("bias_space"), toString(t.space)},
                                       {QStringLiteral("light_placements"), placements},
                                       {QStringLiteral("current"), candidateJson(t.current)},
                                       {QStringLiteral("best"), candidateJson(t.candidates[t.best])},
                                       {QStringLiteral("improves"), t.improves},
                                       {QStringLiteral("noise_pixels"), errorNoisePixels(t.current.misclassifiedPixels)},
                                       {QStringLiteral("front"), front},
                                       {QStringLiteral("candidates"), all}})
                 .toJson(QJsonDocument::Indented);
}

// The front of false shadow against false light, the best and the current setting marked.
void printTradeOff(const BiasTuning& t, QSize size, const QString& rendererString)
{
    out() << "renderer: " << rendererString << '\n'
          << "bias in " << toString(t.space) << " units, " << t.candidates.size() << " settings x " << t.placements.size()
          << " light directions at " << size.width() << "x" << size.height() << ", against the hard reference\n\n"
          << "the trade-off (no other setting has less of both), in % of measured pixels:\n"
          << QStringLiteral("  %1 %2 %3 %4\n").arg(QStringLiteral("slope"), 8).arg(QStringLiteral("min"), 8)
                 .arg(QStringLiteral("false shadow"), 13).arg(QStringLiteral("false light"), 12);
    for (const std::size_t i : t.front) {
        const BiasCandidate& c = t.candidates[i];
        QStringList marks;
        if (i == t.best)
            marks << QStringLiteral("best");
        if (i == t.currentCandidate)
            marks << QStringLiteral("as set");
        out() << QStringLiteral("  %1 %2 %3 %4%5\n").arg(c.slope, 8).arg(c.min, 8).arg(percent(c.falseShadow), 13)
                     .arg(percent(c.falseLight), 12).arg(marks.isEmpty() ? QString() : QStringLiteral("   <- ") + marks.join(QStringLiteral(", ")));
    }
}

// The current and the best setting, and whether changing to the best is worth it.
void printVerdict(const BiasTuning& t)
{
    const BiasCandidate& best = t.candidates[t.best];
    out() << '\n' << "as set   " << measured(t.current) << '\n' << "best     " << measured(best) << '\n';
    if (t.improves) {
        out() << "apply with: --set bias.space=" << toString(t.space) << " --set bias.slope=" << best.slope << " --set bias.min=" << best.min << '\n';
    } else {
        const auto noise = [](const BiasCandidate& c) { return QString::number(errorNoisePixels(c.misclassifiedPixels), 'f', 0); };
        out() << QStringLiteral("the current setting is already on the knee: %1 px against the best point's %2 px differ by less than "
                                "their noise (±%3 and ±%4 px); nothing to change\n")
                     .arg(pixels(t.current), pixels(best), noise(t.current), noise(best));
    }
}

} // namespace

int runTune(const QStringList& arguments)
{
    return guarded(QStringLiteral("tune"), [&] {
        QCommandLineParser parser;
        addTuneOptions(parser);
        if (!parseArguments(parser, QStringLiteral("tune"), arguments))
            return kExitOk;
        const Settings settings = settingsFromOptions(parser);
        const QSize size = parseSize(parser.value(QStringLiteral("size")), QStringLiteral("size"), kTuneSize);
        const bool save = parser.isSet(QStringLiteral("out"));
        const QString file = parser.value(QStringLiteral("out"));
        if (save)
            checkOutputFile(file, QStringLiteral("--out"));   // before minutes of work

        HeadlessRenderer headless;
        const BiasTuning t = searchBias(headless.renderer(), settings, size);
        if (save)
            saveSettingsFile(file, tunedSettings(settings, t));   // whole or not at all
        if (parser.isSet(QStringLiteral("json"))) {
            printJson(t, headless.renderer().rendererString());
            return kExitOk;
        }
        printTradeOff(t, size, headless.renderer().rendererString());
        printVerdict(t);
        if (save)
            out() << "wrote " << QFileInfo(file).absoluteFilePath() << (t.improves ? QString() : QStringLiteral(" (the settings as set)")) << '\n';
        return kExitOk;
    });
}

} // namespace shadowlab::cli
