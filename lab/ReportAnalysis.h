#pragma once

#include "AccuracyMeter.h"
#include "Flicker.h"
#include "SampleStats.h"
#include "Settings.h"
#include "TexelDensity.h"

#include <QImage>
#include <QSize>

#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// What a row costs on the fronts, the picks and the charts (report --cost): its frame's wall
// time on the machine that measured it, or a count that is the same on any GPU (FrameCounts):
// the shadow lookups' taps, or the samples the shadow pass wrote.
enum class CostAxis { Time, Taps, ShadowSamples };

// A row's error over the instants of an animation (report --times, --animation): one entry an
// instant, in order of time. Empty for a still measurement.
struct AnimatedError {
    std::vector<double> times;              // seconds of scene.time
    std::vector<double> misclassified;      // share of the measured pixels, 0..1
    std::vector<double> areaMae;            // 0..1; empty when the area reference was not traced
    std::vector<double> dssim;

    bool measured() const { return !times.empty(); }
    // The instant with the most misclassified pixels (its index).
    std::size_t worst() const;
};
double mean(const std::vector<double>& values);

struct ReportRow {
    QString label;              // labels of identical configurations joined with " = "
    QStringList assignments;
    QString light;              // lightDescription(): rows of different lights are never compared
    SampleStats shadowPass;     // wall ms per pass, the shadow pass running every frame
    // Its wall ms summed over the timed frames, a frame: less than a pass where a cache (or a
    // still scene) leaves it out of some.
    double shadowPerFrame = 0.0;
    SampleStats litPass;
    SampleStats frame;
    AccuracyResult accuracy;
    FlickerResult flicker;      // over a sub-texel camera path (frames 0: not measured)
    // Over an animation: every instant's error; `accuracy` is then the worst instant's, so the
    // fronts and the picks weigh a moving scene at its worst, and the frame time is the scene's
    // playing.
    AnimatedError animation;
    // Over the animation's first instants at 60 frames a second, the camera still: flips the
    // reference does not have (measureTimeFlicker()). Not measured for a still scene.
    FlickerResult timeFlicker;
    TexelDensity density;       // screen pixels per shadow texel over the measured receivers
    FrameCounts counts;         // what one shadow and one lit pass ask of any GPU (FrameStats.h)
    CostAxis costAxis = CostAxis::Time;     // what costOf() weighs
    bool paretoFront = false;   // on its light's front of frame time against misclassified pixels
    bool areaFront = false;     // ... against the MAE of the area light (never when it was not traced)
    bool defaults = false;      // the base settings; its error image is shown
    bool tutorial = false;      // the classic tutorial configuration; its error image is shown
    int sweepIndex = 0;         // its place in the whole sweep, whichever share measured it
    QString renderer;           // GL_RENDERER of the machine that measured it
    QString machine;            // machineFacts() of that machine
};

// The row's cost on its axis: its frame time (median, p10–p90), or its count with a band of
// kCountBand either way, so counts within about twice that of each other tie.
SampleStats costOf(const ReportRow& row);
inline constexpr double kCountBand = 0.01;
// A cost in the row's unit: "12.3 ms", "4.19 M taps", "2.10 M shadow-pass samples".
QString costText(const ReportRow& row, double cost);
// The axis as a chart's title names it, and as --cost and report.json name it ("time", "taps",
// "samples"); nullopt for a name that is none.
QString costAxisTitle(CostAxis axis);
QString costAxisKey(CostAxis axis);
std::optional<CostAxis> costAxisFromKey(const QString& key);
// Whether costs on `axis` are times of the machine that measured them (compared only there).
inline bool isTime(CostAxis axis) { return axis == CostAxis::Time; }

// What `row`'s times were taken on: its renderer, CPU and cores ("llvmpipe (...) (AMD EPYC 7B13,
// 2 cores)"). Rows are compared (on a front, a chart) only with rows of the same light timed on
// the same: times from two machines say nothing of each other.
QString timedOn(const ReportRow& row);
bool comparable(const ReportRow& a, const ReportRow& b);

// The two errors a front is drawn on: misclassified pixels against the hard reference, and
// the mean absolute error against the area light.
enum class ErrorAxis { Misclassified, AreaMae };

// The row's error on `axis` as a count of pixels (ErrorNoise.h): misclassified pixels, or the
// MAE times the pixels measured; and its share of the pixels measured.
double errorPixels(const ReportRow& row, ErrorAxis axis);
double errorShare(const ReportRow& row, ErrorAxis axis);
int measuredPixels(const ReportRow& row, ErrorAxis axis);

// Marks paretoFront and areaFront among the rows of each light. A row beats another only when
// it is better on both axes beyond their noise: clearly faster (its p90 below the other's p10)
// and clearly more accurate (their error bands apart, ErrorNoise.h). Rows that tie on either
// axis stay on the front together, so a ladder of small steps cannot chain the front away to
// its one end; and as only clear differences count, a second run gives the same front.
void markParetoFronts(std::vector<ReportRow>& rows);

// The groups of comparable rows in the order their first rows appear, each named by its light,
// and by its renderer and machine too where the rows come from more than one.
QStringList lightsOf(const std::vector<ReportRow>& rows);
// The name of `row`'s group among `rows`, as lightsOf() names it.
QString lightOf(const ReportRow& row, const std::vector<ReportRow>& rows);
// Whether the rows were measured on more than one renderer or machine (a merged comparison).
bool severalMachines(const std::vector<ReportRow>& rows);

// The rows of the group `light` (lightsOf()) on the front of `axis`, fastest first.
std::vector<const ReportRow*> frontOf(const std::vector<ReportRow>& rows, const QString& light, ErrorAxis axis);

// 1 - mean SSIM of the frame against it shaded with the reference: 0 when alike, an error
// that grows like the others.
double dssim(const ReportRow& row);

// Above this DSSIM against both references a frame is visibly wrong: acne, or a moiré of
// partial shadow that misclassified pixels and the area MAE barely see. Clean rows of real
// models score about 0.001, moiré rows 0.05 to 0.2 (tests/tst_RealModels.cpp holds every
// technique under it).
inline constexpr double kVisibleDssim = 0.01;
// Why `row`'s picture is visibly wrong (unlike the hard reference's picture, and the area
// reference's where traced, beyond kVisibleDssim), or empty when it is not. Such a row is never
// on a front nor recommended: it beats no other row either.
QString visiblyWrong(const ReportRow& row);
// The same for one measurement (the accuracy dock's sweep points).
QString visiblyWrong(const AccuracyResult& result);
// The area MAE's ± (ErrorNoise.h) in percent.
double areaNoisePercent(const ReportRow& row);

// What to pick under one light, and why: the report's first section and its terminal summary's
// last lines. Only rows whose picture is not visibly wrong are picked; rows that tie with the
// pick within the noise of time (p10-p90 overlap) and of the error (ErrorNoise.h) are named as
// ties, and of tied rows the faster (or, tied in time, the more accurate) is the pick.
struct Recommendation {
    enum class Kind {
        Cheapest,       // of the rows with nothing visibly wrong that none such is clearly faster than, the most accurate
        MostAccurate,   // the fewest misclassified pixels within kRecommendationBudget x the cheapest's cost
        ClosestToArea,  // the smallest MAE against the area light, at any cost
        Only,           // the one row under its light whose picture is not visibly wrong
        LeastWrong,     // every row's picture is visibly wrong: the one least unlike a reference's
    };
    Kind kind = Kind::Cheapest;
    const ReportRow* row = nullptr;
    std::vector<const ReportRow*> ties;
    double budget = 0.0;            // MostAccurate: the cost it was chosen within (costOf())
    bool sameAsCheapest = false;    // MostAccurate: nothing within the budget is clearly more accurate
    QString title() const;          // "Cheapest with nothing visibly wrong", ...
    QString reason() const;         // why this row, in figures, and its ties
};

// The cost a row may take to be "most accurate within a cost": this times the cheapest clean
// row's (its median frame time, or its count).
inline constexpr double kRecommendationBudget = 2.0;

// The picks for the group `light` (lightsOf()): none where no row was measured; LeastWrong alone
// where every row is visibly wrong; ClosestToArea only where the area light was traced.
std::vector<Recommendation> recommend(const std::vector<ReportRow>& rows, const QString& light);
// The rows of `light` that no pick may be, for their picture (visiblyWrong()).
std::vector<const ReportRow*> visiblyWrongRows(const std::vector<ReportRow>& rows, const QString& light);

struct ReportFacts {
    QString scene;
    QSize size;
    int frames = 0;             // timed frames per configuration at most...
    int minFrames = 0;          // ...and at least, where its times held sooner
    int warmup = 0;
    QString renderer;
    QString machine;            // CPU, cores, memory, OS, Qt and Embree versions
    int areaSamplesPerPixel = 0;
    double lightRadius = 0.0;
    double areaNoiseFloor = 0.0;
    double raysPerSecond = 0.0;
    int referenceComputations = 0;
    double seconds = 0.0;       // the whole run (merged: the parts' together)
    QString sweep;              // the sweep's fingerprint: what was measured, whoever measured it
    int configurations = 0;     // in the whole sweep, whichever share this report measured
    int shard = 1;              // this report measured share `shard` of `shards` (1 of 1: all)
    int shards = 1;
    int parts = 1;              // reports merged into this one (report --merge)

    // One ray a pixel reads 0 or 1 everywhere and shows no spread: the noise floor is unknown.
    bool areaNoiseKnown() const { return areaSamplesPerPixel > 1; }
    // How often the reference was traced: "once", "3 times".
    QString tracedText() const
    {
        return referenceComputations == 1 ? QStringLiteral("once") : QStringLiteral("%1 times").arg(referenceComputations);
    }
};

// "ortho light at (-2, 4, -1) towards (0, 0, 0)": what makes two rows' errors comparable.
QString lightDescription(const Settings& settings);

// The part of an error image (ShadowMetrics' errorImage()) where its misclassified pixels are
// densest, enlarged `factor` times without smoothing; a null image when it has none.
QImage zoomOnErrors(const QImage& errors, int factor = 4);

// CPU model, cores, memory, OS, Qt and Embree versions, one line.
QString machineFacts();

} // namespace shadowlab
