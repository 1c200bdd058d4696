#include "ReportWriter.h"

#include "ErrorNoise.h"
#include "FrameStatsText.h"
#include "MessageText.h"
#include "ReportChart.h"
#include "ReportFormat.h"

#include <QBuffer>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace shadowlab {

using reportformat::number;
using namespace reportchart;

namespace {

QString pngDataUri(const QImage& image)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return QStringLiteral("data:image/png;base64,") + QString::fromLatin1(bytes.toBase64());
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
                     .arg(number(r.frame.median, 2), number(r.frame.p10, 2), number(r.frame.p90, 2),
                          // A pass a cache leaves out of some frames costs less a frame than a pass.
                          r.shadowPass.count > 0 && r.shadowPerFrame < 0.95 * r.shadowPass.median
                              ? QStringLiteral("%1 (%2 a frame)").arg(number(r.shadowPass.median, 2), number(r.shadowPerFrame, 2))
                              : number(r.shadowPass.median, 2));
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
