#pragma once

#include "ReportAnalysis.h"
#include "Settings.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <vector>

namespace shadowlab {

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
    double seconds = 0.0;       // the whole run
};

// "ortho light at (-2, 4, -1) towards (0, 0, 0)": what makes two rows' errors comparable.
QString lightDescription(const Settings& settings);

// The part of an error image (ShadowMetrics' errorImage()) where its misclassified pixels are
// densest, enlarged `factor` times without smoothing; a null image when it has none.
QImage zoomOnErrors(const QImage& errors, int factor = 4);

// Writes report.csv, report.json and a self-contained report.html (inline SVG charts of each
// error against time with its Pareto front and the noise of both axes, the table without its
// columns of zeros, and the error images of the best and worst rows). Each file is written
// whole or not at all; throws OutputError when one cannot be.
void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts);

// CPU model, cores, memory, OS, Qt and Embree versions, one line.
QString machineFacts();

} // namespace shadowlab
