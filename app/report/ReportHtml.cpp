#include "ReportWriter.h"

#include "ErrorNoise.h"
#include "FrameStatsText.h"
#include "MessageText.h"
#include "ReportFormat.h"

#include <QBuffer>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace shadowlab {

using reportformat::number;

namespace {

QString html(QString text)
{
    return text.toHtmlEscaped();
}

QString pngDataUri(const QImage& image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return QStringLiteral("data:image/png;base64,") + QString::fromLatin1(bytes.toBase64());
}

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

// Colours of the lights' fronts and points, in the order the lights first appear.
const char* const kLightColours[] = {"#e8710a", "#1a73e8", "#188038", "#a142f4", "#d93025", "#12a4af", "#9e6a03", "#5f6368"};

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

// "±3 px, 0.0017 % of 176,553 pixels": what the smallest band means for these rows.
QString smallestBandText(const std::vector<ReportRow>& rows, ErrorAxis axis)
{
    int pixels = 0;
    for (const ReportRow& r : rows)
        pixels = std::max(pixels, measuredPixels(r, axis));
    const double band = errorNoisePixels(0.0);
    return QStringLiteral("±%1 px is %2 % of %3 measured pixels").arg(band).arg(percentText(100.0 * band / std::max(1, pixels)), QLocale(QLocale::English).toString(pixels));
}

double errorPercent(const ReportRow& r, ErrorAxis axis)
{
    return 100.0 * errorShare(r, axis);
}

QLatin1String lightColour(const ReportRow& r, const std::vector<ReportRow>& rows, const QStringList& lights)
{
    return QLatin1String(kLightColours[std::max<qsizetype>(0, lights.indexOf(lightOf(r, rows))) % std::size(kLightColours)]);
}

// A point's colour: its light's, as the legend gives it.
using Colour = std::function<QLatin1String(const ReportRow&)>;

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

// A figure with the whole error image and the part where its errors are densest, enlarged.
QString errorFigure(const QString& title, const ReportRow& row)
{
    QString figure = QStringLiteral("<figure><img alt=\"%1\" src=\"%2\"><figcaption>%3: %1 — %4 % misclassified (%5 % false shadow, %6 % false light)</figcaption></figure>")
                         .arg(html(row.label), pngDataUri(row.accuracy.hardErrors), html(title), percentText(100 * row.accuracy.hard.misclassified),
                              percentText(100 * row.accuracy.hard.falseShadow), percentText(100 * row.accuracy.hard.falseLight));
    const QImage zoom = zoomOnErrors(row.accuracy.hardErrors);
    figure += zoom.isNull() ? QStringLiteral("<figure><figcaption>%1: no misclassified pixels to zoom on</figcaption></figure>").arg(html(title))
                            : QStringLiteral("<figure><img class=\"zoom\" alt=\"%1, zoomed\" src=\"%2\"><figcaption>%3, where its errors are densest, 4× enlarged</figcaption></figure>")
                                  .arg(html(row.label), pngDataUri(zoom), html(title));
    return figure;
}

// The table of every configuration. A column of errors that is zero in every row says one thing
// for all of them: it becomes a sentence under the table.
QString configurationTable(const std::vector<ReportRow>& rows, const QStringList& lights)
{
    struct Column {
        QString heading;
        std::function<double(const ReportRow&)> percent;
    };
    const std::vector<Column> errors{
        {QStringLiteral("false shadow %"), [](const ReportRow& r) { return 100 * r.accuracy.hard.falseShadow; }},
        {QStringLiteral("false light %"), [](const ReportRow& r) { return 100 * r.accuracy.hard.falseLight; }},
        {QStringLiteral("MAE %"), [](const ReportRow& r) { return 100 * r.accuracy.hard.mae; }},
        {QStringLiteral("RMSE %"), [](const ReportRow& r) { return 100 * r.accuracy.hard.rmse; }},
        {QStringLiteral("area RMSE %"), [](const ReportRow& r) { return 100 * r.accuracy.area.rmse; }},
    };
    std::vector<const Column*> shown;
    QStringList zero;
    for (const Column& c : errors) {
        const bool allZero = std::all_of(rows.begin(), rows.end(), [&](const ReportRow& r) { return c.percent(r) < 0.0005; });
        if (allZero)
            zero << c.heading.chopped(2);
        else
            shown.push_back(&c);
    }
    const bool area = std::any_of(rows.begin(), rows.end(), [](const ReportRow& r) { return measuredPixels(r, ErrorAxis::AreaMae) > 0; });

    const bool machines = severalMachines(rows);
    QString table = QStringLiteral("<h2>All configurations</h2><table><tr><th>configuration</th>%1%2<th>on the front</th><th>frame ms (p10–p90)</th>"
                                   "<th>shadow pass ms</th><th>lit pass ms</th><th>misclassified %</th><th>misclassified px</th>")
                        .arg(lights.size() > 1 ? QStringLiteral("<th>light</th>") : QString(),
                             machines ? QStringLiteral("<th>renderer</th>") : QString());
    if (area)
        table += QStringLiteral("<th>area MAE %</th>");
    for (const Column* c : shown)
        table += QStringLiteral("<th>%1</th>").arg(html(c->heading));
    table += QStringLiteral("<th>DSSIM</th><th>texels ≤ 1 px %</th></tr>");
    for (const ReportRow& r : rows) {
        QStringList fronts;
        if (r.paretoFront)
            fronts << QStringLiteral("misclassified");
        if (r.areaFront)
            fronts << QStringLiteral("area");
        // Left off the fronts for its picture, with the reason.
        if (const QString wrong = visiblyWrong(r); !wrong.isEmpty())
            fronts << QStringLiteral("<span class=\"wrong\" title=\"%1\">left out: visibly wrong</span>").arg(html(wrong));
        const double misclassified = errorPixels(r, ErrorAxis::Misclassified);
        table += QStringLiteral("<tr%1><td title=\"%2\">%3</td>%4<td>%5</td><td>%6 (%7–%8)</td><td>%9</td>")
                     .arg(r.paretoFront || r.areaFront ? QStringLiteral(" class=\"front\"") : QString())
                     .arg(html(r.assignments.join(QLatin1Char(' '))), html(r.label),
                          (lights.size() > 1 ? QStringLiteral("<td>%1</td>").arg(lights.indexOf(lightOf(r, rows)) + 1) : QString())
                              + (machines ? QStringLiteral("<td title=\"%1\">%2</td>").arg(html(r.machine), html(r.renderer)) : QString()),
                          fronts.join(QStringLiteral(", ")))
                     .arg(number(r.frame.median, 2), number(r.frame.p10, 2), number(r.frame.p90, 2), number(r.shadowPass.median, 2));
        table += QStringLiteral("<td>%1</td><td>%2</td><td>%3 ± %4</td>")
                     .arg(number(r.litPass.median, 2), percentText(100 * r.accuracy.hard.misclassified), number(misclassified, 0),
                          number(errorNoisePixels(misclassified), 0));
        if (area)
            table += QStringLiteral("<td>%1 ± %2</td>").arg(number(100 * r.accuracy.area.mae, 3), number(areaNoisePercent(r), 3));
        for (const Column* c : shown)
            table += QStringLiteral("<td>%1</td>").arg(number(c->percent(r), 3));
        table += QStringLiteral("<td>%1</td><td>%2</td></tr>").arg(number(dssim(r), 5), number(100 * r.density.fineShare(), 1));
    }
    table += QStringLiteral("</table><p>DSSIM: 1 − the mean SSIM (Wang et al. 2004: 11 × 11 Gaussian window, σ 1.5) of the frame's luma "
                            "against the same frame shaded with the hard reference's visibility; 0 when a reader would see the same "
                            "picture. A row over %1 against both the hard and the area reference's picture is visibly wrong (acne, or a "
                            "moiré of partial shadow that misclassified pixels miss): it is left off the fronts and beats no other row. "
                            "Texels ≤ 1 px: the share of the measured receivers inside the light's map whose shadow texel "
                            "covers at most one screen pixel (blue in the texel density view).</p>")
                 .arg(kVisibleDssim);
    if (!zero.isEmpty())
        table += QStringLiteral("<p>Every configuration has %1 below 0.0005 %: left out of the table.</p>").arg(html(zero.join(QStringLiteral(", "))));
    return table;
}

// What each configuration asks of any GPU: counts, unlike the times, the same on every one.
QString countsTable(const std::vector<ReportRow>& rows)
{
    QString table = QStringLiteral("<h2>Counts</h2><p>What one shadow pass and one frame ask of the GPU, counted, the same on any GPU "
                                   "where the times above are this machine's: the draws and samples passed (GL_SAMPLES_PASSED) of each "
                                   "pass, the shadow-map texels a pass cleared, the texels a moments blur wrote, the shadow storage's "
                                   "memory, and the shadow taps: the technique's texture reads per lookup times the fragments that "
                                   "looked up.</p><table><tr><th>configuration</th><th>shadow draws</th><th>shadow-pass samples</th>"
                                   "<th>texels cleared</th><th>blur texels</th><th>map</th><th>lit draws</th><th>lit samples</th>"
                                   "<th>taps per lookup</th><th>shadow taps</th></tr>");
    for (const ReportRow& r : rows) {
        const FrameCounts& n = r.counts;
        table += QStringLiteral("<tr><td title=\"%1\">%2</td><td>%3</td><td>%4</td><td>%5</td><td>%6</td><td>%7</td>")
                     .arg(html(r.assignments.join(QLatin1Char(' '))), html(r.label))
                     .arg(n.shadow.draws)
                     .arg(countText(n.shadow.samples), countText(n.clearedTexels), countText(n.blurTexels), html(bytesText(n.mapBytes)));
        table += QStringLiteral("<td>%1</td><td>%2</td><td>%3</td><td>%4</td></tr>")
                     .arg(n.lit.draws)
                     .arg(countText(n.lit.samples))
                     .arg(n.tapsPerLookup)
                     .arg(countText(n.taps()));
    }
    return table + QStringLiteral("</table>");
}

// The configurations whose shadow flickers; one sentence when none does.
QString flickerSection(const std::vector<ReportRow>& rows)
{
    const int frames = std::accumulate(rows.begin(), rows.end(), 0, [](int m, const ReportRow& r) { return std::max(m, r.flicker.frames); });
    QString section = QStringLiteral("<h2>Flicker</h2>");
    if (std::none_of(rows.begin(), rows.end(), [](const ReportRow& r) { return r.flicker.measured(); }))
        return section + QStringLiteral("<p>Not measured (--flicker-frames %1: flicker is a change between two frames).</p>").arg(frames);
    const auto flickers = [](const ReportRow& r) { return 100 * std::max(r.flicker.flicker, r.flicker.meanChange) >= 0.0005; };
    const auto flickering = std::count_if(rows.begin(), rows.end(), flickers);
    section += QStringLiteral("<p>The camera the light is fitted to walks %1 frames in sub-texel steps while the measured pixels stay put: "
                              "the share of receiver pixels whose shadow flips between consecutive frames, and the mean change of visibility.")
                   .arg(frames);
    // Flicker of 0 means nothing where the maps never moved: say which it is.
    const auto still = std::count_if(rows.begin(), rows.end(), [](const ReportRow& r) { return r.flicker.measured() && r.flicker.mapMoves == 0; });
    if (still > 0)
        section += QStringLiteral(" In %1 of %2 configurations the light's maps did not move at all during the walk: the casters, not the "
                                  "camera's view, bound the fitted volume, so this camera cannot show shimmer there (a camera whose view cuts "
                                  "the shadows, or the city, can).")
                       .arg(still)
                       .arg(rows.size());
    if (flickering == 0)
        return section + QStringLiteral(" No configuration flickers above 0.0005 % on either.</p>");
    section += flickering < qsizetype(rows.size()) ? QStringLiteral(" The other %1 configurations flicker below 0.0005 % on both.</p>").arg(rows.size() - std::size_t(flickering))
                                                   : QStringLiteral("</p>");
    section += QStringLiteral("<table><tr><th>configuration</th><th>flips %</th><th>worst pair %</th><th>mean change %</th></tr>");
    for (const ReportRow& r : rows) {
        if (flickers(r))
            section += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td></tr>")
                           .arg(html(r.label), number(100 * r.flicker.flicker, 3), number(100 * r.flicker.worstPair, 3), number(100 * r.flicker.meanChange, 3));
    }
    return section + QStringLiteral("</table>");
}

// The page's head and style, and the facts of the run under its title.
QString pageHead(const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    return QStringLiteral(R"(<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>ShadowLab report: %1</title>
<style>
body{font:14px/1.45 system-ui,sans-serif;margin:2em auto;max-width:1100px;color:#222;background:#fafafa}
h1{font-size:1.6em}h2{margin-top:2em;font-size:1.2em}
.facts{color:#555}.chart{width:100%;max-width:760px;background:#fff;border:1px solid #ddd}
.grid{stroke:#eee}.tick{font-size:11px;fill:#777}.axis{font-size:12px;fill:#444}
.pt{opacity:.55}.onfront{opacity:1;stroke:#222;stroke-width:1}.front{fill:none;stroke-width:2}.front.ties{stroke-width:1;stroke-dasharray:4 3;opacity:.5}.spread{stroke-width:1.5;opacity:.45}.spread.noise{stroke-width:3;opacity:.25}.grid.minor{stroke:#f4f4f4}
.label{font-size:11px;fill:#333}.leader{stroke:#999;stroke-width:.7}
table{border-collapse:collapse;background:#fff;font-size:12.5px}td,th{border:1px solid #ddd;padding:3px 7px;text-align:right}
td:first-child,th:first-child{text-align:left}tr.front td{background:#fff4e8}.wrong{color:#b00}
.images{display:flex;gap:16px;flex-wrap:wrap}.images figure{margin:0}.images img{max-width:520px;border:1px solid #ccc}.images img.zoom{image-rendering:pixelated}
.lights span{display:inline-block;width:12px;height:12px;margin:0 4px 0 12px;vertical-align:middle;border-radius:6px}
.picks dt{margin-top:.5em}.picks dd{margin-left:1.5em;color:#444}
.key span{display:inline-block;width:12px;height:12px;margin:0 4px 0 12px;vertical-align:middle}
</style></head><body>
<h1>Shadow error against %16: %1</h1>
<p class="facts">%2x%3 pixels, %4 timed frames per configuration after %5 warm-up, shadow pass every frame.<br>
Renderer: %6%15<br>Machine: %7<br>
Reference: one shadow ray per pixel (hard) and %8 per pixel of a disk light of radius %9 (area; %10);
%11 Mrays/s; traced %12 for %13 configurations. Whole run: %14 s.</p>
)")
        .arg(html(facts.scene))
        .arg(facts.size.width())
        .arg(facts.size.height())
        .arg(facts.minFrames < facts.frames ? QStringLiteral("%1–%2 (until its median and p10–p90 held)").arg(facts.minFrames).arg(facts.frames)
                                        : QString::number(facts.frames))
        .arg(facts.warmup)
        .arg(html(facts.renderer), html(facts.machine))
        .arg(facts.areaSamplesPerPixel == 1 ? QStringLiteral("1 ray") : QStringLiteral("%1 stratified rays").arg(facts.areaSamplesPerPixel))
        .arg(facts.lightRadius)
        .arg(facts.areaNoiseKnown() ? QStringLiteral("noise floor %1 %").arg(percentText(100 * facts.areaNoiseFloor))
                                           : QStringLiteral("noise floor unknown from one ray a pixel: use --area-samples 2 or more"))
        .arg(number(facts.raysPerSecond * 1e-6, 2))
        .arg(facts.tracedText())
        .arg(rows.size())
        .arg(number(facts.seconds, 1))
        .arg(facts.renderer.contains(QStringLiteral("llvmpipe")) || facts.renderer.contains(QStringLiteral("softpipe"))
                 ? QStringLiteral(" — <b>a software rasteriser: its times are CPU time, and a GPU ranks costs differently</b> (a "
                                  "moment filter's blur or a wide kernel costs far less there); measure on the GPU and put the reports "
                                  "side by side with <code>report --merge</code>")
                 : QString())
        .arg(rows.empty() || isTime(rows.front().costAxis) ? QStringLiteral("run time")
             : rows.front().costAxis == CostAxis::Taps   ? QStringLiteral("shadow taps, the same on any GPU")
                                                          : QStringLiteral("shadow-pass samples, the same on any GPU"));
}

// Whether this report is one share of a sweep, or several reports put together.
QString partsNote(const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    if (facts.shards > 1)
        return QStringLiteral("<p class=\"facts\">Share %1 of %2 of the sweep: %3 of its %4 configurations, each front among them only. "
                              "Put the shares together with <code>shadowlab report --merge</code>.</p>")
            .arg(facts.shard)
            .arg(facts.shards)
            .arg(rows.size())
            .arg(facts.configurations);
    if (facts.parts > 1)
        return QStringLiteral("<p class=\"facts\">Put together from %1 reports (<code>report --merge</code>); the whole run is their times "
                              "added.%2</p>")
            .arg(facts.parts)
            .arg(!severalMachines(rows) ? QString()
                 : rows.empty() || isTime(rows.front().costAxis)
                     ? QStringLiteral(" Measured on several machines: a row's times are compared only with rows of its own machine, and each "
                                      "machine has its own front.")
                     : QStringLiteral(" Measured on several machines: the fronts weigh counts, the same on any GPU, so rows of every machine "
                                      "are compared."));
    return QString();
}

// Under several lights, the colour of each: every light has its own front.
QString lightsLegend(const QStringList& lights)
{
    if (lights.size() <= 1)
        return QString();
    QString legend = QStringLiteral("<p class=\"lights\">Lights (each has its own front; errors under different lights are not comparable, "
                                    "nor times taken on different machines, where the front weighs time):");
    for (qsizetype i = 0; i < lights.size(); ++i)
        legend += QStringLiteral("<br><span style=\"background:%1\"></span>%2").arg(QLatin1String(kLightColours[std::size_t(i) % std::size(kLightColours)]), html(lights[i]));
    return legend + QStringLiteral("</p>");
}

// The report's answer first: under each light, what to pick and why, with its ties; and the
// rows no pick may be, for their picture.
QString recommendationSection(const std::vector<ReportRow>& rows, const QStringList& lights)
{
    QString section = QStringLiteral("<h2>What to pick</h2>");
    for (const QString& light : lights) {
        if (lights.size() > 1)
            section += QStringLiteral("<h3>Under the %1</h3>").arg(html(light));
        const std::vector<Recommendation> picks = recommend(rows, light);
        if (picks.empty()) {
            section += QStringLiteral("<p>Nothing: no configuration under this light has a pixel facing the light in view, so none was "
                                      "measured.</p>");
            continue;
        }
        section += QStringLiteral("<dl class=\"picks\">");
        for (const Recommendation& pick : picks)
            section += QStringLiteral("<dt>%1: <b>%2</b></dt><dd>%3</dd>").arg(html(pick.title()), html(pick.row->label), html(pick.reason()));
        section += QStringLiteral("</dl>");
        if (const auto wrong = visiblyWrongRows(rows, light); !wrong.empty() && picks.front().kind != Recommendation::Kind::LeastWrong) {
            QStringList names;
            for (const ReportRow* r : wrong)
                names << QStringLiteral("<span title=\"%1\">%2</span>").arg(html(visiblyWrong(*r)), html(r->label));
            section += QStringLiteral("<p>Never picked, as their picture is visibly wrong (DSSIM over %1 against both references: acne, or "
                                      "a moiré of partial shadow): %2.</p>")
                           .arg(kVisibleDssim)
                           .arg(names.join(QStringLiteral(", ")));
        }
    }
    return section + QStringLiteral("<p class=\"facts\">Two rows tie when neither is clearly better: costs whose bands overlap (times' "
                                    "p10–p90; counts within about 2 %), errors whose noise bands overlap (below). Of rows tied in error the "
                                    "cheaper is picked; of rows tied in cost, for the cheapest, the more accurate.</p>");
}

// Both charts and what their dots, lines and bars mean; a pair per light projection where the
// sweep has both (an ortho and a perspective map differ in time and error by their nature, and
// their points among each other's read as outliers).
QString chartsSection(const std::vector<ReportRow>& rows, const QStringList& lights)
{
    std::vector<std::pair<QString, std::vector<ReportRow>>> groups;
    for (const ReportRow& r : rows) {
        const QString projection = r.light.section(u' ', 0, 0);
        auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == projection; });
        if (group == groups.end())
            group = groups.insert(groups.end(), {projection, {}});
        group->second.push_back(r);
    }
    // Colours by the light's name among all rows, as the legend gives them.
    const Colour colour = [&](const ReportRow& r) { return lightColour(r, rows, lights); };
    QString section;
    for (const auto& [projection, group] : groups) {
        const QString of = groups.size() > 1 ? QStringLiteral(", %1 lights").arg(html(projection)) : QString();
        section += QStringLiteral("<h2>Misclassified pixels against the hard reference%1</h2>").arg(of);
        section += chart(group, colour, QStringLiteral("misclassified pixels, % (|V − V_ref| > 0.5)"), ErrorAxis::Misclassified);
        section += QStringLiteral("<h2>Mean absolute error against the area light%1</h2>").arg(of);
        section += chart(group, colour, QStringLiteral("MAE of visibility, %"), ErrorAxis::AreaMae);
    }
    const bool time = rows.empty() || isTime(rows.front().costAxis);
    section += QStringLiteral("<p>Large dots: the Pareto front of each light, on each chart its own; the line steps through those that "
                              "are more accurate than every %2 one. A configuration leaves the front only when another is "
                              "better on both axes beyond their noise: %3 and clearly more accurate (their error bands apart; the "
                              "bars up and down). "
                              "Configurations that tie on either axis stay on the front together. An error is a count of pixels (MAE "
                              "times the pixels measured, as fully wrong pixels), and a count n is known to n ± max(3, 2√n): a sub-texel "
                              "move of camera or light slides the pixels along every shadow edge in or out of error, scattering a count "
                              "by about √n, and fewer than a few pixels are not resolved at all (%1). Identical configurations are "
                              "measured once, their names joined with “=”.</p>")
                   .arg(html(smallestBandText(rows, ErrorAxis::Misclassified)))
                   .arg(time ? QStringLiteral("faster") : QStringLiteral("cheaper"))
                   .arg(time ? QStringLiteral("clearly faster (its p90 below the other's p10; the bars across)")
                             : QStringLiteral("clearly cheaper (a count more than about 2 % below the other's)"));
    return section;
}

// The error images of the defaults, the tutorial, and the most and least accurate configuration.
QString errorImages(const std::vector<ReportRow>& rows)
{
    if (rows.empty())
        return QString();
    const auto byError = [](const ReportRow& a, const ReportRow& b) { return a.accuracy.hard.misclassified < b.accuracy.hard.misclassified; };
    const ReportRow* best = &*std::min_element(rows.begin(), rows.end(), byError);
    const ReportRow* worst = &*std::max_element(rows.begin(), rows.end(), byError);
    QString section = QStringLiteral("<h2>Error images</h2><p class=\"key\">Against the hard reference:<span style=\"background:#eb28c8\"></span>false shadow (acne)"
                                     "<span style=\"background:#28dceb\"></span>false light (peter panning, leaks). Beside each, the part of the frame "
                                     "where its errors are densest, enlarged.</p>");
    std::vector<std::pair<QString, const ReportRow*>> shown;
    for (const ReportRow& r : rows) {
        if (r.defaults)
            shown.emplace_back(QStringLiteral("Defaults"), &r);
    }
    for (const ReportRow& r : rows) {
        if (r.tutorial)
            shown.emplace_back(QStringLiteral("Tutorial configuration"), &r);
    }
    shown.emplace_back(QStringLiteral("Most accurate"), best);
    shown.emplace_back(QStringLiteral("Least accurate"), worst);
    for (const auto& [title, row] : shown)
        section += QStringLiteral("<div class=\"images\">") + errorFigure(title, *row) + QStringLiteral("</div>");
    return section;
}

} // namespace

QByteArray reportHtml(const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    // The lights in order of appearance: each has its own front and colour.
    const QStringList lights = lightsOf(rows);
    QString page = pageHead(rows, facts) + partsNote(rows, facts);
    page += lightsLegend(lights);
    page += recommendationSection(rows, lights);
    page += chartsSection(rows, lights);
    page += configurationTable(rows, lights);
    page += countsTable(rows);
    page += flickerSection(rows);
    page += errorImages(rows);
    page += QStringLiteral("</body></html>\n");
    return page.toUtf8();
}

} // namespace shadowlab
