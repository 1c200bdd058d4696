#include "ReportAnalysis.h"

#include "ErrorNoise.h"

#include <algorithm>

namespace shadowlab {

namespace {

const ErrorMetrics& metrics(const ReportRow& row, ErrorAxis axis)
{
    return axis == ErrorAxis::Misclassified ? row.accuracy.hard : row.accuracy.area;
}

bool clearlyFaster(const SampleStats& a, const SampleStats& b)
{
    return a.p90 < b.p10;
}

bool beats(const ReportRow& b, const ReportRow& a, ErrorAxis axis)
{
    return b.light == a.light && clearlyFaster(b.frame, a.frame) && clearlyFewer(errorPixels(b, axis), errorPixels(a, axis));
}

void markFront(std::vector<ReportRow>& rows, ErrorAxis axis, bool ReportRow::*flag)
{
    for (ReportRow& a : rows) {
        const bool measured = measuredPixels(a, axis) > 0;
        a.*flag = measured && std::none_of(rows.begin(), rows.end(), [&](const ReportRow& b) { return beats(b, a, axis); });
    }
}

} // namespace

double errorShare(const ReportRow& row, ErrorAxis axis)
{
    const ErrorMetrics& m = metrics(row, axis);
    return axis == ErrorAxis::Misclassified ? m.misclassified : m.mae;
}

int measuredPixels(const ReportRow& row, ErrorAxis axis)
{
    return metrics(row, axis).pixels;
}

double errorPixels(const ReportRow& row, ErrorAxis axis)
{
    return errorShare(row, axis) * measuredPixels(row, axis);
}

void markParetoFronts(std::vector<ReportRow>& rows)
{
    markFront(rows, ErrorAxis::Misclassified, &ReportRow::paretoFront);
    markFront(rows, ErrorAxis::AreaMae, &ReportRow::areaFront);
}

QStringList lightsOf(const std::vector<ReportRow>& rows)
{
    QStringList lights;
    for (const ReportRow& r : rows) {
        if (!lights.contains(r.light))
            lights << r.light;
    }
    return lights;
}

std::vector<const ReportRow*> frontOf(const std::vector<ReportRow>& rows, const QString& light, ErrorAxis axis)
{
    std::vector<const ReportRow*> front;
    for (const ReportRow& r : rows) {
        if (r.light == light && (axis == ErrorAxis::Misclassified ? r.paretoFront : r.areaFront))
            front.push_back(&r);
    }
    std::stable_sort(front.begin(), front.end(), [](const ReportRow* a, const ReportRow* b) { return a->frame.median < b->frame.median; });
    return front;
}

} // namespace shadowlab
