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
    bool paretoFront = false;   // on its light's front of frame time against misclassified pixels
    bool areaFront = false;     // ... against the MAE of the area light (never when it was not traced)
    bool defaults = false;      // the base settings; its error image is shown
    bool tutorial = false;      // the classic tutorial configuration; its error image is shown
};

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

// The lights in the order their first rows appear.
QStringList lightsOf(const std::vector<ReportRow>& rows);

// The rows of `light` on the front of `axis`, fastest first.
std::vector<const ReportRow*> frontOf(const std::vector<ReportRow>& rows, const QString& light, ErrorAxis axis);

} // namespace shadowlab
