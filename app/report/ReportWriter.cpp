#include "ReportWriter.h"

#include "MessageText.h"
#include "OutputFile.h"

#include <embree3/rtcore_config.h>

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSysInfo>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

void writeFile(const QString& path, const QByteArray& bytes)
{
    writeOutputFile(path, bytes);
}

QString csvField(QString text)
{
    if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"')))
        text = QLatin1Char('"') + text.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return text;
}

QString number(double v, int decimals = 4)
{
    return QString::number(v, 'f', decimals);
}

QJsonObject statsJson(const SampleStats& s)
{
    return {{QStringLiteral("median_ms"), s.median}, {QStringLiteral("p10_ms"), s.p10}, {QStringLiteral("p90_ms"), s.p90}};
}

QJsonObject metricsJson(const ErrorMetrics& m)
{
    return {{QStringLiteral("pixels"), m.pixels},         {QStringLiteral("misclassified"), m.misclassified},
            {QStringLiteral("false_shadow"), m.falseShadow}, {QStringLiteral("false_light"), m.falseLight},
            {QStringLiteral("mae"), m.mae},                 {QStringLiteral("rmse"), m.rmse}};
}

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

// An inline SVG scatter plot of `value(row)` against frame time, Pareto front joined.
QString chart(const std::vector<ReportRow>& rows, const QString& yTitle, const std::function<double(const ReportRow&)>& value)
{
    const double w = 760, h = 420, left = 70, right = 20, top = 20, bottom = 50;
    double xMax = 0.0, yMax = 0.0;
    for (const ReportRow& r : rows) {
        xMax = std::max(xMax, r.frame.median);
        yMax = std::max(yMax, value(r));
    }
    xMax = xMax > 0.0 ? xMax * 1.08 : 1.0;
    yMax = yMax > 0.0 ? yMax * 1.12 : 1.0;
    // Enough decimals that five ticks up to yMax read as five different numbers.
    const int yDecimals = std::clamp(2 - int(std::floor(std::log10(yMax / 5.0))), 0, 8);
    auto px = [&](double x) { return left + x / xMax * (w - left - right); };
    auto py = [&](double y) { return h - bottom - y / yMax * (h - top - bottom); };

    QString svg = QStringLiteral("<svg viewBox=\"0 0 %1 %2\" class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\">").arg(w).arg(h);
    for (int i = 0; i <= 5; ++i) {
        const double x = xMax * i / 5.0, y = yMax * i / 5.0;
        svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%1\" y2=\"%3\" class=\"grid\"/>").arg(px(x)).arg(top).arg(h - bottom);
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"tick\" text-anchor=\"middle\">%3</text>").arg(px(x)).arg(h - bottom + 18).arg(number(x, 1));
        svg += QStringLiteral("<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\" class=\"grid\"/>").arg(left).arg(py(y)).arg(w - right);
        svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"tick\" text-anchor=\"end\">%3</text>").arg(left - 6).arg(py(y) + 4).arg(number(y, yDecimals));
    }
    svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"axis\" text-anchor=\"middle\">frame time, shadow pass every frame (ms, median)</text>")
               .arg((left + w - right) / 2)
               .arg(h - 10);
    svg += QStringLiteral("<text x=\"16\" y=\"%1\" class=\"axis\" text-anchor=\"middle\" transform=\"rotate(-90 16 %1)\">%2</text>")
               .arg((top + h - bottom) / 2)
               .arg(html(yTitle));

    std::vector<const ReportRow*> front;
    for (const ReportRow& r : rows) {
        if (r.paretoFront)
            front.push_back(&r);
    }
    std::sort(front.begin(), front.end(), [](const ReportRow* a, const ReportRow* b) { return a->frame.median < b->frame.median; });
    QString points;
    for (const ReportRow* r : front)
        points += QStringLiteral("%1,%2 ").arg(px(r->frame.median)).arg(py(value(*r)));
    svg += QStringLiteral("<polyline points=\"%1\" class=\"front\"/>").arg(points);
    for (const ReportRow& r : rows) {
        svg += QStringLiteral("<circle cx=\"%1\" cy=\"%2\" r=\"%3\" class=\"%4\"><title>%5: %6 ms, %7</title></circle>")
                   .arg(px(r.frame.median))
                   .arg(py(value(r)))
                   .arg(r.paretoFront ? 6 : 4)
                   .arg(r.paretoFront ? QStringLiteral("pt onfront") : QStringLiteral("pt"))
                   .arg(html(r.label))
                   .arg(number(r.frame.median, 2))
                   .arg(number(value(r), 4));
        if (r.paretoFront || r.label == u"defaults")
            svg += QStringLiteral("<text x=\"%1\" y=\"%2\" class=\"label\">%3</text>").arg(px(r.frame.median) + 8).arg(py(value(r)) - 6).arg(html(r.label));
    }
    return svg + QStringLiteral("</svg>");
}

} // namespace

void markParetoFront(std::vector<ReportRow>& rows)
{
    for (ReportRow& a : rows) {
        a.paretoFront = std::none_of(rows.begin(), rows.end(), [&](const ReportRow& b) {
            const bool noWorse = b.frame.median <= a.frame.median && b.accuracy.hard.misclassified <= a.accuracy.hard.misclassified;
            const bool better = b.frame.median < a.frame.median || b.accuracy.hard.misclassified < a.accuracy.hard.misclassified;
            return &a != &b && noWorse && better;
        });
    }
}

QString machineFacts()
{
    QString cpu;
    QFile cpuinfo(QStringLiteral("/proc/cpuinfo"));
    if (cpuinfo.open(QIODevice::ReadOnly)) {
        for (const QByteArray& line : cpuinfo.readAll().split('\n')) {
            if (line.startsWith("model name")) {
                cpu = QString::fromUtf8(line.mid(line.indexOf(':') + 1)).trimmed();
                break;
            }
        }
    }
    QString memory;
    QFile meminfo(QStringLiteral("/proc/meminfo"));
    if (meminfo.open(QIODevice::ReadOnly)) {
        const QByteArray first = meminfo.readLine();
        memory = QStringLiteral("%1 GiB").arg(first.split(':').value(1).trimmed().split(' ').value(0).toDouble() / (1024.0 * 1024.0), 0, 'f', 1);
    }
    return QStringLiteral("%1, %2 cores, %3 memory, %4, Qt %5, Embree %6")
        .arg(cpu.isEmpty() ? QSysInfo::currentCpuArchitecture() : cpu)
        .arg(QThread::idealThreadCount())
        .arg(memory.isEmpty() ? QStringLiteral("?") : memory, QSysInfo::prettyProductName(), QString::fromLatin1(qVersion()),
             QStringLiteral(RTC_VERSION_STRING));
}

void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    if (!QDir().mkpath(directory))
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("cannot create the report folder '%1'").arg(displayText(directory)));
    const QDir dir(directory);

    QString csv = QStringLiteral("label,settings,shadow_ms,shadow_p10,shadow_p90,lit_ms,lit_p10,lit_p90,frame_ms,frame_p10,frame_p90,"
                                 "misclassified,false_shadow,false_light,mae,rmse,area_mae,area_rmse,pareto,flicker,flicker_change\n");
    QJsonArray jsonRows;
    for (const ReportRow& r : rows) {
        const ErrorMetrics& h = r.accuracy.hard;
        const ErrorMetrics& a = r.accuracy.area;
        csv += QStringList{csvField(r.label), csvField(r.assignments.join(QLatin1Char(' '))), number(r.shadowPass.median), number(r.shadowPass.p10),
                           number(r.shadowPass.p90), number(r.litPass.median), number(r.litPass.p10), number(r.litPass.p90), number(r.frame.median),
                           number(r.frame.p10), number(r.frame.p90), number(h.misclassified, 6), number(h.falseShadow, 6), number(h.falseLight, 6),
                           number(h.mae, 6), number(h.rmse, 6), number(a.mae, 6), number(a.rmse, 6),
                           r.paretoFront ? QStringLiteral("1") : QStringLiteral("0"), number(r.flicker.flicker, 6), number(r.flicker.meanChange, 6)}
                   .join(QLatin1Char(','))
            + QLatin1Char('\n');
        jsonRows.append(QJsonObject{{QStringLiteral("label"), r.label},
                                    {QStringLiteral("settings"), QJsonArray::fromStringList(r.assignments)},
                                    {QStringLiteral("shadow_pass_wall"), statsJson(r.shadowPass)},
                                    {QStringLiteral("lit_pass_wall"), statsJson(r.litPass)},
                                    {QStringLiteral("frame_wall"), statsJson(r.frame)},
                                    {QStringLiteral("hard_reference"), metricsJson(h)},
                                    {QStringLiteral("area_reference"), metricsJson(a)},
                                    {QStringLiteral("pareto_front"), r.paretoFront},
                                    {QStringLiteral("flicker"), QJsonObject{{QStringLiteral("flips"), r.flicker.flicker},
                                                                            {QStringLiteral("worst_pair"), r.flicker.worstPair},
                                                                            {QStringLiteral("mean_change"), r.flicker.meanChange},
                                                                            {QStringLiteral("frames"), r.flicker.frames}}}});
    }
    writeFile(dir.filePath(QStringLiteral("report.csv")), csv.toUtf8());

    const QJsonObject json{{QStringLiteral("scene"), facts.scene},
                           {QStringLiteral("size"), QStringLiteral("%1x%2").arg(facts.size.width()).arg(facts.size.height())},
                           {QStringLiteral("frames"), facts.frames},
                           {QStringLiteral("warmup"), facts.warmup},
                           {QStringLiteral("renderer"), facts.renderer},
                           {QStringLiteral("machine"), facts.machine},
                           {QStringLiteral("area_samples_per_pixel"), facts.areaSamplesPerPixel},
                           {QStringLiteral("light_radius"), facts.lightRadius},
                           {QStringLiteral("area_noise_floor"), facts.areaNoiseFloor},
                           {QStringLiteral("rays_per_second"), facts.raysPerSecond},
                           {QStringLiteral("reference_computations"), facts.referenceComputations},
                           {QStringLiteral("seconds"), facts.seconds},
                           {QStringLiteral("rows"), jsonRows}};
    writeFile(dir.filePath(QStringLiteral("report.json")), QJsonDocument(json).toJson(QJsonDocument::Indented));

    const ReportRow* best = nullptr;
    const ReportRow* worst = nullptr;
    for (const ReportRow& r : rows) {
        if (!best || r.accuracy.hard.misclassified < best->accuracy.hard.misclassified)
            best = &r;
        if (!worst || r.accuracy.hard.misclassified > worst->accuracy.hard.misclassified)
            worst = &r;
    }

    QString page = QStringLiteral(R"(<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>ShadowLab report: %1</title>
<style>
body{font:14px/1.45 system-ui,sans-serif;margin:2em auto;max-width:1100px;color:#222;background:#fafafa}
h1{font-size:1.6em}h2{margin-top:2em;font-size:1.2em}
.facts{color:#555}.chart{width:100%;max-width:760px;background:#fff;border:1px solid #ddd}
.grid{stroke:#eee}.tick{font-size:11px;fill:#777}.axis{font-size:12px;fill:#444}
.pt{fill:#6b7a90;opacity:.8}.onfront{fill:#e8710a;opacity:1}.front{fill:none;stroke:#e8710a;stroke-width:2}
.label{font-size:11px;fill:#333}
table{border-collapse:collapse;background:#fff;font-size:12.5px}td,th{border:1px solid #ddd;padding:3px 7px;text-align:right}
td:first-child,th:first-child{text-align:left}tr.front td{background:#fff4e8}
.images{display:flex;gap:16px;flex-wrap:wrap}.images figure{margin:0}.images img{max-width:520px;border:1px solid #ccc}
.key span{display:inline-block;width:12px;height:12px;margin:0 4px 0 12px;vertical-align:middle}
</style></head><body>
<h1>Shadow error against run time: %1</h1>
<p class="facts">%2x%3 pixels, %4 timed frames per configuration after %5 warm-up, shadow pass every frame.<br>
Renderer: %6<br>Machine: %7<br>
Reference: one shadow ray per pixel (hard) and %8 stratified rays per pixel of a disk light of radius %9 (area; noise floor %10);
%11 Mrays/s; traced %12 time(s) for %13 configurations. Whole run: %14 s.</p>
)")
                       .arg(html(facts.scene))
                       .arg(facts.size.width())
                       .arg(facts.size.height())
                       .arg(facts.frames)
                       .arg(facts.warmup)
                       .arg(html(facts.renderer), html(facts.machine))
                       .arg(facts.areaSamplesPerPixel)
                       .arg(facts.lightRadius)
                       .arg(number(facts.areaNoiseFloor, 4))
                       .arg(number(facts.raysPerSecond * 1e-6, 2))
                       .arg(facts.referenceComputations)
                       .arg(rows.size())
                       .arg(number(facts.seconds, 1));
    page += QStringLiteral("<h2>Misclassified pixels against the hard reference</h2>");
    page += chart(rows, QStringLiteral("misclassified pixels, % (|V − V_ref| > 0.5)"),
                  [](const ReportRow& r) { return 100.0 * r.accuracy.hard.misclassified; });
    page += QStringLiteral("<h2>Mean absolute error against the area light</h2>");
    page += chart(rows, QStringLiteral("MAE of visibility"), [](const ReportRow& r) { return r.accuracy.area.mae; });
    page += QStringLiteral("<p>Orange: the Pareto front on time and misclassified share: no other configuration is both faster and more accurate.</p>");

    page += QStringLiteral("<h2>All configurations</h2><table><tr><th>configuration</th><th>shadow pass ms</th><th>lit pass ms</th><th>frame ms (p10–p90)</th>"
                           "<th>misclassified %</th><th>false shadow %</th><th>false light %</th><th>MAE</th><th>RMSE</th><th>area MAE</th><th>area RMSE</th></tr>");
    for (const ReportRow& r : rows) {
        const ErrorMetrics& h = r.accuracy.hard;
        page += QStringLiteral("<tr%1><td title=\"%2\">%3</td><td>%4</td><td>%5</td><td>%6 (%7–%8)</td><td>%9</td><td>%10</td><td>%11</td><td>%12</td><td>%13</td><td>%14</td><td>%15</td></tr>")
                    .arg(r.paretoFront ? QStringLiteral(" class=\"front\"") : QString())
                    .arg(html(r.assignments.join(QLatin1Char(' '))), html(r.label))
                    .arg(number(r.shadowPass.median, 2), number(r.litPass.median, 2), number(r.frame.median, 2), number(r.frame.p10, 2),
                         number(r.frame.p90, 2), number(100 * h.misclassified, 3), number(100 * h.falseShadow, 3))
                    .arg(number(100 * h.falseLight, 3), number(h.mae, 4), number(h.rmse, 4), number(r.accuracy.area.mae, 4),
                         number(r.accuracy.area.rmse, 4));
    }
    page += QStringLiteral("</table>");
    page += QStringLiteral("<h2>Flicker</h2><p>The camera the light is fitted to walks in sub-texel steps while the measured pixels stay put: "
                           "the share of receiver pixels whose shadow flips between consecutive frames, and the mean change of visibility.</p>"
                           "<table><tr><th>configuration</th><th>flips %</th><th>worst pair %</th><th>mean change</th><th>frames</th></tr>");
    for (const ReportRow& r : rows) {
        page += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>")
                    .arg(html(r.label), number(100 * r.flicker.flicker, 3), number(100 * r.flicker.worstPair, 3), number(r.flicker.meanChange, 5))
                    .arg(r.flicker.frames);
    }
    page += QStringLiteral("</table>");
    if (best && worst) {
        page += QStringLiteral("<h2>Error images</h2><p class=\"key\">Against the hard reference:<span style=\"background:#eb28c8\"></span>false shadow (acne)"
                               "<span style=\"background:#28dceb\"></span>false light (peter panning, leaks)</p><div class=\"images\">");
        for (const auto& [title, row] : {std::pair(QStringLiteral("Best"), best), std::pair(QStringLiteral("Worst"), worst)}) {
            page += QStringLiteral("<figure><img alt=\"%1\" src=\"%2\"><figcaption>%3: %1 (%4% misclassified)</figcaption></figure>")
                        .arg(html(row->label), pngDataUri(row->accuracy.hardErrors), title, number(100 * row->accuracy.hard.misclassified, 3));
        }
        page += QStringLiteral("</div>");
    }
    page += QStringLiteral("</body></html>\n");
    writeFile(dir.filePath(QStringLiteral("report.html")), page.toUtf8());
}

} // namespace shadowlab
