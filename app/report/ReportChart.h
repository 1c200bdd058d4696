#pragma once

#include "ReportAnalysis.h"

#include <QLatin1String>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

// The report page's charts, and what the rest of the page shares with them.
namespace shadowlab::reportchart {

// Colours of the lights' fronts and points, in the order the lights first appear.
inline constexpr const char* kLightColours[] = {"#e8710a", "#1a73e8", "#188038", "#a142f4", "#d93025", "#12a4af", "#9e6a03", "#5f6368"};
// A row's colour in a chart.
using Colour = std::function<QLatin1String(const ReportRow&)>;

// `text` escaped for HTML.
QString html(QString text);
// A share in percent with the digits its size needs, never an exponent: 0.001, 0.02, 1.5, 40.
QString percentText(double v);
// What the smallest noise band on `axis` means for these rows, in pixels and percent.
QString smallestBandText(const std::vector<ReportRow>& rows, ErrorAxis axis);
// The colour of `r`'s light among `lights`.
QLatin1String lightColour(const ReportRow& r, const std::vector<ReportRow>& rows, const QStringList& lights);
// An inline SVG chart of each row's error on `axis` against its cost (see the definition).
QString chart(const std::vector<ReportRow>& rows, const Colour& colour, const QString& yTitle, ErrorAxis axis);

} // namespace shadowlab::reportchart
