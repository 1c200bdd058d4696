#include "ReportWriter.h"

#include "ErrorNoise.h"
#include "ReportFormat.h"

namespace shadowlab {

using reportformat::number;

namespace {

QString csvField(QString text)
{
    if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"')))
        text = QLatin1Char('"') + text.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return text;
}

// The counts' columns; a count not taken is empty.
QStringList countFields(const FrameCounts& c)
{
    const auto count = [](std::int64_t n) { return n < 0 ? QString() : QString::number(n); };
    return {QString::number(c.shadow.draws), count(c.shadow.primitives), count(c.shadow.samples), count(c.clearedTexels), count(c.blurTexels),
            count(c.blurBytes), count(c.mapBytes), QString::number(c.lit.draws), count(c.lit.primitives), count(c.lit.samples),
            QString::number(c.tapsPerLookup), count(c.lookupFragments), count(c.taps()), count(c.copiedTexels), count(c.cacheBytes)};
}

} // namespace

QByteArray reportCsv(const std::vector<ReportRow>& rows)
{
    // Times in ms, errors in percent of the measured pixels (MAE and RMSE in percent of full
    // visibility), as the page shows them; every column says its unit, but dssim (1 - mean
    // SSIM), a plain number. The renderer and machine that measured the row close it (a merged
    // report can hold several). Flicker not measured (--flicker-frames 0) is empty, not 0: no
    // flicker is a finding.
    QString csv = QStringLiteral("label,settings,shadow_ms,shadow_p10_ms,shadow_p90_ms,lit_ms,lit_p10_ms,lit_p90_ms,frame_ms,frame_p10_ms,frame_p90_ms,"
                                 "misclassified_pct,false_shadow_pct,false_light_pct,mae_pct,rmse_pct,area_mae_pct,area_rmse_pct,pareto,light,"
                                 "flicker_pct,flicker_change_pct,misclassified_px,misclassified_noise_px,area_pareto,area_mae_noise_pct,dssim,fine_texels_pct,"
                                 "shadow_draws,shadow_primitives,shadow_samples,cleared_texels,blur_texels,blur_bytes,map_bytes,"
                                 "lit_draws,lit_primitives,lit_samples,taps_per_lookup,lookup_fragments,taps,copied_texels,cache_bytes,shadow_per_frame_ms,"
                                 "renderer,machine\n");
    for (const ReportRow& r : rows) {
        const bool flickerMeasured = r.flicker.measured();
        const ErrorMetrics& h = r.accuracy.hard;
        const ErrorMetrics& a = r.accuracy.area;
        csv += (QStringList{csvField(r.label), csvField(r.assignments.join(QLatin1Char(' '))), number(r.shadowPass.median),
                           number(r.shadowPass.p10), number(r.shadowPass.p90), number(r.litPass.median), number(r.litPass.p10), number(r.litPass.p90),
                           number(r.frame.median), number(r.frame.p10), number(r.frame.p90), number(100 * h.misclassified, 4),
                           number(100 * h.falseShadow, 4), number(100 * h.falseLight, 4), number(100 * h.mae, 4), number(100 * h.rmse, 4),
                           number(100 * a.mae, 4), number(100 * a.rmse, 4), r.paretoFront ? QStringLiteral("1") : QStringLiteral("0"), csvField(r.light),
                           flickerMeasured ? number(100 * r.flicker.flicker, 4) : QString(),
                           flickerMeasured ? number(100 * r.flicker.meanChange, 4) : QString(),
                           number(errorPixels(r, ErrorAxis::Misclassified), 0), number(errorNoisePixels(errorPixels(r, ErrorAxis::Misclassified)), 1),
                           r.areaFront ? QStringLiteral("1") : QStringLiteral("0"), number(areaNoisePercent(r), 4), number(dssim(r), 6),
                           number(100 * r.density.fineShare(), 3)}
                   + countFields(r.counts) + QStringList{number(r.shadowPerFrame), csvField(r.renderer), csvField(r.machine)})
                   .join(QLatin1Char(','))
            + QLatin1Char('\n');
    }
    return csv.toUtf8();

}

} // namespace shadowlab
