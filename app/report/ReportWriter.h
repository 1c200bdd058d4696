#pragma once

#include "AccuracyMeter.h"
#include "Flicker.h"
#include "SampleStats.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

struct ReportRow {
    QString label;
    QStringList assignments;
    SampleStats shadowPass;     // wall ms per pass, the shadow pass running every frame
    SampleStats litPass;
    SampleStats frame;
    AccuracyResult accuracy;
    FlickerResult flicker;      // over a sub-texel camera path (frames 0: not measured)
    bool paretoFront = false;   // no other row is both faster and more accurate (hard reference)
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

// Marks ReportRow::paretoFront on (frame median, hard misclassified share).
void markParetoFront(std::vector<ReportRow>& rows);

// Writes report.csv, report.json and a self-contained report.html (inline SVG charts of error
// against time with the Pareto front, the table, and the error images of the best and worst
// rows). Each file is written whole or not at all; throws OutputError when one cannot be.
void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts);

// CPU model, cores, memory, OS, Qt and Embree versions, one line.
QString machineFacts();

} // namespace shadowlab
