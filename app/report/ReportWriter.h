#pragma once

#include "AccuracyMeter.h"
#include "Flicker.h"
#include "SampleStats.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

struct ReportRow {
    QString label;              // labels of identical configurations joined with " = "
    QStringList assignments;
    QString light;              // lightDescription(): rows of different lights are never compared
    SampleStats shadowPass;     // wall ms per pass, the shadow pass running every frame
    SampleStats litPass;
    SampleStats frame;
    AccuracyResult accuracy;
    FlickerResult flicker;      // over a sub-texel camera path (frames 0: not measured)
    bool paretoFront = false;   // no other row of the same light beats it (see markParetoFront)
    bool defaults = false;      // the base settings; its error image is shown
    bool tutorial = false;      // the classic tutorial configuration; its error image is shown
};

struct ReportFacts {
    QString scene;
    QSize size;
    int frames = 0;
    int warmup = 0;
    QString renderer;
    QString machine;            // CPU, cores, memory, OS, Qt and Embree versions
    int areaSamplesPerPixel = 0;
    double lightRadius = 0.0;
    double areaNoiseFloor = 0.0;
    double raysPerSecond = 0.0;
    int referenceComputations = 0;
    double seconds = 0.0;       // the whole run
};

// Marks ReportRow::paretoFront on frame time and hard misclassified share, among the rows of
// the same light. Timing is noisy, so one row beats another only when it is at least as
// accurate and faster beyond both p10–p90 spreads, or more accurate and not slower beyond them:
// two runs of the same sweep give the same front.
void markParetoFront(std::vector<ReportRow>& rows);

// "ortho light at (-2, 4, -1) towards (0, 0, 0)": what makes two rows' errors comparable.
QString lightDescription(const Settings& settings);

// The part of an error image (ShadowMetrics' errorImage()) where its misclassified pixels are
// densest, enlarged `factor` times without smoothing; a null image when it has none.
QImage zoomOnErrors(const QImage& errors, int factor = 4);

// Writes report.csv, report.json and a self-contained report.html (inline SVG charts of error
// against time with the Pareto front, the table, and the error images of the best and worst
// rows). Each file is written whole or not at all; throws OutputError when one cannot be.
void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts);

// CPU model, cores, memory, OS, Qt and Embree versions, one line.
QString machineFacts();

} // namespace shadowlab
