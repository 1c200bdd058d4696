#include "ReportChart.h"

#include "ErrorNoise.h"
#include "FrameStatsText.h"
#include "MessageText.h"
#include "ReportFormat.h"

#include <QLocale>

#include <algorithm>
#include <cmath>
#include <numeric>

// The report page's error-against-cost charts (SVG), drawn from the rows.
namespace shadowlab::reportchart {

using reportformat::number;

QString html(QString text)
{
    return text.toHtmlEscaped();
}

namespace {

constexpr double kLabelGap = 5.0;      // clear space around a label: labels that touch read as one word

// A label's width in the 11 px sans-serif label font (DejaVu Sans's advances, rounded up): wide
// letters count wide, so "msm" beside "vsm" is not taken for room.
double labelWidth(const QString& text)
{
    double width = 0.0;
    for (const QChar c : text) {
        if (QStringLiteral("mW").contains(c))
            width += 11.0;
        else if (QStringLiteral("wM").contains(c))
            width += 9.6;
        else if (QStringLiteral("ijlI.,:;'|! ").contains(c))
            width += 3.6;
        else if (QStringLiteral("frt()[]").contains(c))
            width += 4.8;
        else if (c.isUpper())
            width += 8.7;
        else
            width += 7.0;
    }
    return width;
}
constexpr double kLabelHeight = 13.0;

struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Ticks for a log axis from `lo` to `hi` (powers of ten): 1, 2 and 5 of each decade when
// there are few decades, the decades alone otherwise.
std::vector<double> logTicks(double lo, double hi)
{
    std::vector<double> ticks;
    const int decades = int(std::lround(std::log10(hi / lo)));
    for (double d = lo; d <= hi * 1.0001; d *= 10.0) {
        for (double m : {1.0, 2.0, 5.0}) {
            if ((m == 1.0 || decades <= 3) && d * m <= hi * 1.0001)
                ticks.push_back(d * m);
        }
    }
    return ticks;
}

bool onFront(const ReportRow& r, ErrorAxis axis)
{
    return axis == ErrorAxis::Misclassified ? r.paretoFront : r.areaFront;
}

// The error's noise band (ErrorNoise.h) in percent of the pixels measured: {low, high}.
std::pair<double, double> noiseBand(const ReportRow& r, ErrorAxis axis)
{
    const double n = errorPixels(r, axis), band = errorNoisePixels(n), pixels = std::max(1, measuredPixels(r, axis));
    return {100.0 * std::max(0.0, n - band) / pixels, 100.0 * (n + band) / pixels};
}

double errorPercent(const ReportRow& r, ErrorAxis axis)
{
    return 100.0 * errorShare(r, axis);
}

// A point's colour: its light's, as the legend gives it.

// Where a chart puts its values: frame time (ms) across on a log axis from a 1-2-5 tick below
// the fastest p10 to one above the slowest p90, so the fast cluster where nearly every choice
// lies is as readable as a slow outlier ten times its time; the error (%) up on a log axis of
// whole decades, with a line of its own below them for 0 %.
struct ChartScale {
    static constexpr double w = 760, h = 440, left = 70, right = 20, top = 20, bottom = 50;
    double xMin = 1.0;
    double xMax = 10.0;
    double yMin = 0.01;
    double yMax = 1.0;
    bool anyZero = false;
    double zeroBand = 0.0;

    double px(double x) const
    {
        const double t = std::log10(std::clamp(x, xMin, xMax) / xMin) / std::log10(xMax / xMin);
        return left + t * (w - left - right);
    }
    double py(double y) const
    {
        if (y <= 0.0)
            return h - bottom;
        const double t = std::log10(std::max(y, yMin) / yMin) / std::log10(yMax / yMin);
        return h - bottom - zeroBand - t * (h - top - bottom - zeroBand);
    }
};

// The 1-2-5 step at or below `v` (down) or at or above it (up).
double roundStep(double v, bool up)
{
    const double power = std::pow(10.0, std::floor(std::log10(v)));
    const double steps[] = {1.0, 2.0, 5.0, 10.0};
    if (up) {
        for (double m : steps) {
            if (power * m >= v * 0.9999)
                return power * m;
        }
        return power * 10.0;
    }
    double below = power;
    for (double m : steps) {
        if (power * m <= v * 1.0001)
            below = power * m;
    }
    return below;
}

ChartScale chartScale(const std::vector<ReportRow>& rows, ErrorAxis axis)
{
    ChartScale c;
    double xLow = 0.0, xHigh = 0.0, yLow = 0.0, yHigh = 0.0;
    for (const ReportRow& r : rows) {
        const SampleStats cost = costOf(r);
        if (!std::isfinite(cost.p10) || !std::isfinite(cost.p90))
            continue;   // never drawn; the table says what it is
        if (cost.p10 > 0.0)
            xLow = xLow > 0.0 ? std::min(xLow, cost.p10) : cost.p10;
        xHigh = std::max(xHigh, cost.p90);
        const double v = errorPercent(r, axis);
        if (v > 0.0) {
            yLow = yLow > 0.0 ? std::min(yLow, v) : v;
            yHigh = std::max(yHigh, v);
        }
    }
    c.xMin = xLow > 0.0 ? roundStep(xLow, false) : 1.0;
    c.xMax = std::max(xHigh > 0.0 ? roundStep(xHigh, true) : 10.0, c.xMin * 2.0);
    // Whole decades around the values: one outlier at 40 % leaves 0.01 % readable.
    c.yMin = yLow > 0.0 ? std::pow(10.0, std::floor(std::log10(yLow))) : 0.01;
    c.yMax = yHigh > 0.0 ? std::pow(10.0, std::ceil(std::log10(yHigh))) : 1.0;
    if (c.yMax <= c.yMin)
        c.yMax = c.yMin * 10.0;
    // 0 % has no place on a log axis: it gets a line of its own below the lowest decade.
    c.anyZero = std::any_of(rows.begin(), rows.end(), [&](const ReportRow& r) { return errorPercent(r, axis) <= 0.0; });
    c.zeroBand = c.anyZero ? 22.0 : 0.0;
    return c;
}

// The cost axis's ticks: every 1-2-5 step between its ends, or only 1 and 5 of each decade,
// or the decades alone, as many as fit with room between their numbers.
std::vector<double> costTicks(const ChartScale& c)
{
    std::vector<double> all;
    for (double d = std::pow(10.0, std::floor(std::log10(c.xMin))); d <= c.xMax * 1.0001; d *= 10.0) {
        for (double m : {1.0, 2.0, 5.0}) {
            if (d * m >= c.xMin * 0.9999 && d * m <= c.xMax * 1.0001)
                all.push_back(d * m);
        }
    }
    for (const auto& keep : {std::vector<double>{1.0, 2.0, 5.0}, std::vector<double>{1.0, 5.0}, std::vector<double>{1.0}}) {
        std::vector<double> ticks;
        for (double t : all) {
            const double mantissa = t / std::pow(10.0, std::floor(std::log10(t) + 1e-9));
            if (std::any_of(keep.begin(), keep.end(), [&](double m) { return std::abs(mantissa - m) < 1e-6; }) || t == all.front() || t == all.back())
                ticks.push_back(t);
        }
        bool roomy = true;
        for (std::size_t i = 1; i < ticks.size(); ++i)
            roomy = roomy && c.px(ticks[i]) - c.px(ticks[i - 1]) >= 34.0;
        if (roomy)
            return ticks;
    }
    return {all.front(), all.back()};
}

// The grid, its ticks and the two axis titles.
QString chartAxes(const ChartScale& c, const QString& yTitle, CostAxis cost)
{
    const double w = c.w, h = c.h, left = c.left, right = c.right, top = c.top, bottom = c.bottom;
    QString svg;
    for (double x : costTicks(c)) {
        const QString tick = isTime(cost) ? percentText(x) : countText(std::int64_t(std::llround(x)));
        svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%1\" y2=\"%3\" class=\"grid\"/>").arg(c.px(x)).arg(top).arg(h - bottom);
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"tick\" text-anchor=\"middle\">%3</text>").arg(c.px(x)).arg(h - bottom + 18).arg(tick);
    }
    if (c.anyZero) {
        svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\" class=\"grid\"/>").arg(left).arg(c.py(0.0)).arg(w - right);
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"tick\" text-anchor=\"end\">0 %</text>").arg(left - 6).arg(c.py(0.0) + 4);
    }
    for (double y : logTicks(c.yMin, c.yMax)) {
        const bool decade = std::abs(std::log10(y) - std::round(std::log10(y))) < 1e-9;
        svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\" class=\"%4\"/>")
                   .arg(left)
                   .arg(c.py(y))
                   .arg(w - right)
                   .arg(decade ? QStringLiteral("grid") : QStringLiteral("grid minor"));
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"tick\" text-anchor=\"end\">%3 %</text>").arg(left - 6).arg(c.py(y) + 4).arg(percentText(y));
    }
    svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"axis\" text-anchor=\"middle\">%3</text>")
               .arg((left + w - right) / 2)
               .arg(h - 10)
               .arg(html(costAxisTitle(cost)));
    svg += QStringLiteral("<text x=\"16\" y=\"%1\" class=\"axis\" text-anchor=\"middle\" transform=\"rotate(-90 16 %1)\">%2 (log scale)</text>")
               .arg((top + h - bottom) / 2)
               .arg(html(yTitle));
    return svg;
}

// Each light's front, from fast to slow. The solid line steps down through the front points
// that beat every faster one; a thin dashed line joins every front point, the ties with them
// included, so the front reaches as far as its slowest point.
QString frontLines(const std::vector<ReportRow>& rows, const Colour& colour, ErrorAxis axis, const ChartScale& c)
{
    QString svg;
    for (const QString& light : lightsOf(rows)) {
        std::vector<const ReportRow*> steps;
        for (const ReportRow* r : frontOf(rows, light, axis)) {
            if (steps.empty() || errorPercent(*r, axis) < errorPercent(*steps.back(), axis))
                steps.push_back(r);
        }
        const std::vector<const ReportRow*> all = frontOf(rows, light, axis);
        if (all.size() < 2)
            continue;
        // Every front point, fast to slow, joined by a thin dashed line: the ties that the steps
        // leave out are on the front too, as far out as the slowest of them.
        const auto line = [&](const std::vector<const ReportRow*>& points) {
            QString text;
            for (const ReportRow* r : points)
                text += QStringLiteral("%1,%2 ").arg(c.px(costOf(*r).median)).arg(c.py(errorPercent(*r, axis)));
            return text.trimmed();
        };
        if (all.size() > steps.size())
            svg += QStringLiteral("<polyline points=\"%1\" class=\"front ties\" stroke=\"%2\"/>").arg(line(all), colour(*all.front()));
        if (steps.size() >= 2)
            svg += QStringLiteral("<polyline points=\"%1\" class=\"front\" stroke=\"%2\"/>").arg(line(steps), colour(*steps.front()));
    }
    return svg;
}

// Every row's noise bars, then its point; `taken` gets a box around each point, which labels
// keep off.
QString pointsAndBars(const std::vector<ReportRow>& rows, const Colour& colour, ErrorAxis axis, const ChartScale& c, std::vector<Box>& taken)
{
    QString svg;
    for (const ReportRow& r : rows) {
        const SampleStats cost = costOf(r);
        if (!std::isfinite(cost.median))
            continue;   // no count on this axis: the table says why
        const double x = c.px(cost.median), y = c.py(errorPercent(r, axis));
        if (isTime(r.costAxis)) {
            svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\" class=\"spread\" stroke=\"%4\"/>")
                       .arg(c.px(cost.p10))
                       .arg(y)
                       .arg(c.px(cost.p90))
                       .arg(colour(r));
        }
        if (measuredPixels(r, axis) > 0) {
            const auto [low, high] = noiseBand(r, axis);
            svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%1\" y2=\"%3\" class=\"spread noise\" stroke=\"%4\"/>")
                       .arg(x)
                       .arg(c.py(std::min(high, c.yMax)))
                       .arg(c.py(low))
                       .arg(colour(r));
        }
        taken.push_back({x - 6, y - 6, x + 6, y + 6});
    }
    for (const ReportRow& r : rows) {
        if (!std::isfinite(costOf(r).median))
            continue;
        const QString cost = isTime(r.costAxis)
            ? QStringLiteral("%1 ms (p10 %2, p90 %3)").arg(number(r.frame.median, 2), number(r.frame.p10, 2), number(r.frame.p90, 2))
            : costText(r, costOf(r).median) + QStringLiteral(" (%1 ms)").arg(number(r.frame.median, 2));
        svg += QStringLiteral("<circle cx=\"%1\" cy=\"%2\" r=\"%3\" fill=\"%4\" class=\"%5\"><title>%6: %7, %8 %</title></circle>")
                   .arg(c.px(costOf(r).median))
                   .arg(c.py(errorPercent(r, axis)))
                   .arg(onFront(r, axis) ? 6 : 4)
                   .arg(colour(r), onFront(r, axis) ? QStringLiteral("pt onfront") : QStringLiteral("pt"), html(r.label))
                   .arg(html(cost), percentText(errorPercent(r, axis)));
    }
    return svg;
}

// The rows that get a label: the recommended ones first, then the two reference
// configurations, then the front.
std::vector<const ReportRow*> labelledRows(const std::vector<ReportRow>& rows, ErrorAxis axis)
{
    std::vector<const ReportRow*> labelled;
    const auto add = [&](const ReportRow* r) {
        if (std::find(labelled.begin(), labelled.end(), r) == labelled.end())
            labelled.push_back(r);
    };
    for (const QString& light : lightsOf(rows)) {
        for (const Recommendation& pick : recommend(rows, light))
            add(pick.row);
    }
    for (const ReportRow& r : rows) {
        if (r.defaults || r.tutorial)
            add(&r);
    }
    for (const ReportRow& r : rows) {
        if (onFront(r, axis))
            add(&r);
    }
    return labelled;
}

// Where a label `width` wide may go for the point (x, y), in the order tried: beside the point
// first, right then left, above then below, then further up or down (with a leader line).
std::vector<Box> labelPlaces(double x, double y, double width)
{
    std::vector<Box> places;
    for (int away = 0; away < 5; ++away) {
        const double dy = 4 + away * (kLabelHeight + 2);
        for (double side : {1.0, -1.0}) {
            const double x0 = side > 0 ? x + 8 : x - 8 - width;
            places.push_back({x0, y - dy - kLabelHeight, x0 + width, y - dy});
            places.push_back({x0, y + dy, x0 + width, y + dy + kLabelHeight});
        }
    }
    return places;
}

// A point's label: identical configurations' names joined with " = " are shown as the first and
// how many more ("defaults (+3 identical)"; the tooltip and the table name them all); a long
// name is cut at a word.
QString chartLabel(const QString& label)
{
    const QStringList names = label.split(QStringLiteral(" = "));
    QString text = names.front();
    if (text.size() > 32) {
        const qsizetype cut = text.lastIndexOf(u' ', 31);
        text = text.left(cut > 12 ? cut : 31) + QChar(0x2026);
    }
    return names.size() > 1 ? QStringLiteral("%1 (+%2 identical)").arg(text).arg(names.size() - 1) : text;
}

// Labels for the front and the two reference configurations, first fit wins; a label that fits
// nowhere is left out (the point's tooltip and the table still name it).
QString pointLabels(const std::vector<ReportRow>& rows, ErrorAxis axis, const ChartScale& c, std::vector<Box>& taken)
{
    QString svg;
    for (const ReportRow* r : labelledRows(rows, axis)) {
        const QString text = chartLabel(r->label);
        const double x = c.px(costOf(*r).median), y = c.py(errorPercent(*r, axis));
        for (const Box& b : labelPlaces(x, y, labelWidth(text))) {
            const bool inside = b.x0 >= c.left + 2 && b.x1 <= c.w - c.right && b.y0 >= c.top && b.y1 <= c.h - c.bottom;
            const Box clear{b.x0 - kLabelGap, b.y0 - 1.0, b.x1 + kLabelGap, b.y1 + 1.0};
            if (!inside || std::any_of(taken.begin(), taken.end(), [&](const Box& t) { return t.overlaps(clear); }))
                continue;
            if (b.y1 < y - 4 - kLabelHeight || b.y0 > y + 4 + kLabelHeight) {
                const double ly = b.y1 < y ? b.y1 : b.y0;
                svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%4\" class=\"leader\"/>")
                           .arg(x)
                           .arg(y)
                           .arg(b.x0 > x ? b.x0 : b.x1)
                           .arg(ly);
            }
            taken.push_back(b);
            svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"label\">%3</text>").arg(b.x0).arg(b.y1 - 3).arg(html(text));
            break;
        }
    }
    return svg;
}

} // namespace

QString percentText(double v)
{
    // Enough digits for the value's size, never an exponent: 0.001 %, 0.02 %, 1.5 %, 40 %.
    const int decimals = v <= 0.0 ? 0 : std::clamp(1 - int(std::floor(std::log10(v))), 0, 4);
    QString text = QString::number(v, 'f', decimals);
    if (text.contains(QLatin1Char('.'))) {
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(QLatin1Char('.')))
            text.chop(1);
    }
    return text;
}

// "±3 px, 0.0017 % of 176,553 pixels": what the smallest band means for these rows.
QString smallestBandText(const std::vector<ReportRow>& rows, ErrorAxis axis)
{
    int pixels = 0;
    for (const ReportRow& r : rows)
        pixels = std::max(pixels, measuredPixels(r, axis));
    const double band = errorNoisePixels(0.0);
    return QStringLiteral("±%1 px is %2 % of %3 measured pixels").arg(band).arg(percentText(100.0 * band / std::max(1, pixels)), QLocale(QLocale::English).toString(pixels));
}

QLatin1String lightColour(const ReportRow& r, const std::vector<ReportRow>& rows, const QStringList& lights)
{
    return QLatin1String(kLightColours[std::max<qsizetype>(0, lights.indexOf(lightOf(r, rows))) % std::size(kLightColours)]);
}

// An inline SVG scatter plot of each row's error on `axis` (in percent, on a log axis) against
// frame time, with both noises as bars (p10–p90 across, the error's band up and down); each
// light's Pareto front on that axis marked, joined in its colour and labelled, with the
// defaults and the tutorial; labels placed where they hide nothing.
QString chart(const std::vector<ReportRow>& rows, const Colour& colour, const QString& yTitle, ErrorAxis axis)
{
    const ChartScale c = chartScale(rows, axis);
    std::vector<Box> taken;
    QString svg = QStringLiteral("<svg viewBox=\"0 0 %1 %2\" class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\">").arg(c.w).arg(c.h);
    svg += chartAxes(c, yTitle, rows.empty() ? CostAxis::Time : rows.front().costAxis);
    svg += frontLines(rows, colour, axis, c);
    svg += pointsAndBars(rows, colour, axis, c, taken);
    svg += pointLabels(rows, axis, c, taken);
    return svg + QStringLiteral("</svg>");
}

} // namespace shadowlab::reportchart
