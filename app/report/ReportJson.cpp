#include "ReportWriter.h"

#include "ErrorNoise.h"
#include "FrameStatsText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace shadowlab {

namespace {

QJsonObject statsJson(const SampleStats& s)
{
    return {{QStringLiteral("median_ms"), s.median}, {QStringLiteral("p10_ms"), s.p10}, {QStringLiteral("p90_ms"), s.p90},
            {QStringLiteral("min_ms"), s.min}, {QStringLiteral("max_ms"), s.max}, {QStringLiteral("mean_ms"), s.mean},
            {QStringLiteral("count"), s.count}};
}

// The shadow pass's times, and its time summed over the timed frames a frame (less than a pass
// where a cache leaves it out of some).
QJsonObject shadowPassJson(const ReportRow& r)
{
    QJsonObject pass = statsJson(r.shadowPass);
    pass.insert(QStringLiteral("per_frame_ms"), r.shadowPerFrame);
    return pass;
}

QJsonObject metricsJson(const ErrorMetrics& m)
{
    return {{QStringLiteral("pixels"), m.pixels},
            {QStringLiteral("misclassified_pct"), 100 * m.misclassified},
            {QStringLiteral("false_shadow_pct"), 100 * m.falseShadow},
            {QStringLiteral("false_light_pct"), 100 * m.falseLight},
            {QStringLiteral("mae_pct"), 100 * m.mae},
            {QStringLiteral("rmse_pct"), 100 * m.rmse}};
}

// A flicker figure, or null where the walk was not measured (--flicker-frames 0): no flicker
// is a finding, not a default.
QJsonValue flickerValue(const ReportRow& r, double fraction)
{
    return r.flicker.measured() ? QJsonValue(100 * fraction) : QJsonValue();
}

} // namespace

QString errorImageName(std::size_t position)
{
    return QStringLiteral("errors/%1.png").arg(position, 3, 10, QLatin1Char('0'));
}

// Over an animation: each instant's errors, their mean and the worst; null for a still measurement.
QJsonValue animationJson(const AnimatedError& a)
{
    if (!a.measured())
        return QJsonValue();
    const auto percents = [](const std::vector<double>& values) {
        QJsonArray list;
        for (double v : values)
            list.append(100 * v);
        return QJsonObject{{QStringLiteral("each"), list},
                           {QStringLiteral("mean"), values.empty() ? QJsonValue() : QJsonValue(100 * mean(values))},
                           {QStringLiteral("worst"), values.empty() ? QJsonValue() : QJsonValue(100 * *std::max_element(values.begin(), values.end()))}};
    };
    QJsonArray times;
    for (double t : a.times)
        times.append(t);
    return QJsonObject{{QStringLiteral("times"), times},
                       {QStringLiteral("worst_time"), a.times[a.worst()]},
                       {QStringLiteral("misclassified_pct"), percents(a.misclassified)},
                       {QStringLiteral("area_mae_pct"), percents(a.areaMae)},
                       {QStringLiteral("dssim_pct"), percents(a.dssim)}};
}

// Flicker over an animation's frames; null where it was not measured.
QJsonValue timeFlickerJson(const FlickerResult& f)
{
    if (!f.measured())
        return QJsonValue();
    return QJsonObject{{QStringLiteral("flips_pct"), 100 * f.flicker},
                       {QStringLiteral("worst_pair_pct"), 100 * f.worstPair},
                       {QStringLiteral("mean_change_pct"), 100 * f.meanChange},
                       {QStringLiteral("frames"), f.frames}};
}

namespace {

// What to pick under each light, and why (recommend()).
QJsonArray recommendationsJson(const std::vector<ReportRow>& rows)
{
    QJsonArray picks;
    for (const QString& light : lightsOf(rows)) {
        for (const Recommendation& pick : recommend(rows, light)) {
            QJsonArray ties;
            for (const ReportRow* r : pick.ties)
                ties.append(r->label);
            picks.append(QJsonObject{{QStringLiteral("light"), light},
                                     {QStringLiteral("pick"), pick.title()},
                                     {QStringLiteral("label"), pick.row->label},
                                     {QStringLiteral("sweep_index"), pick.row->sweepIndex},
                                     {QStringLiteral("reason"), pick.reason()},
                                     {QStringLiteral("ties"), ties}});
        }
    }
    return picks;
}

} // namespace

QByteArray reportJson(const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    QJsonArray jsonRows;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ReportRow& r = rows[i];
        const ErrorMetrics& h = r.accuracy.hard;
        const ErrorMetrics& a = r.accuracy.area;
        jsonRows.append(QJsonObject{{QStringLiteral("label"), r.label},
                                    {QStringLiteral("sweep_index"), r.sweepIndex},
                                    {QStringLiteral("defaults"), r.defaults},
                                    {QStringLiteral("tutorial"), r.tutorial},
                                    {QStringLiteral("renderer"), r.renderer},
                                    {QStringLiteral("machine"), r.machine},
                                    {QStringLiteral("error_image"), r.accuracy.hardErrors.isNull() ? QJsonValue() : QJsonValue(errorImageName(i))},
                                    {QStringLiteral("settings"), QJsonArray::fromStringList(r.assignments)},
                                    {QStringLiteral("light"), r.light},
                                    {QStringLiteral("shadow_pass_wall"), shadowPassJson(r)},
                                    {QStringLiteral("lit_pass_wall"), statsJson(r.litPass)},
                                    {QStringLiteral("frame_wall"), statsJson(r.frame)},
                                    {QStringLiteral("frames"), r.frame.count},
                                    {QStringLiteral("counts"), countsJson(r.counts)},
                                    {QStringLiteral("cost_axis"), costAxisKey(r.costAxis)},
                                    {QStringLiteral("hard_reference"), metricsJson(h)},
                                    {QStringLiteral("area_reference"), metricsJson(a)},
                                    {QStringLiteral("pareto_front"), r.paretoFront},
                                    {QStringLiteral("area_pareto_front"), r.areaFront},
                                    {QStringLiteral("misclassified_noise_px"), errorNoisePixels(errorPixels(r, ErrorAxis::Misclassified))},
                                    {QStringLiteral("area_mae_noise_pct"), areaNoisePercent(r)},
                                    {QStringLiteral("mean_ssim"), r.accuracy.ssim},
                                    {QStringLiteral("dssim"), dssim(r)},
                                    {QStringLiteral("area_mean_ssim"), r.accuracy.areaSsim ? QJsonValue(*r.accuracy.areaSsim) : QJsonValue()},
                                    {QStringLiteral("visibly_wrong"), visiblyWrong(r).isEmpty() ? QJsonValue() : QJsonValue(visiblyWrong(r))},
                                    {QStringLiteral("area_noise_floor_pct"), 100 * r.accuracy.areaNoiseFloor},
                                    {QStringLiteral("texel_density"), QJsonObject{{QStringLiteral("fine_texels_pct"), 100 * r.density.fineShare()},
                                                                                  {QStringLiteral("fine"), r.density.fine},
                                                                                  {QStringLiteral("median_pixels_per_texel"), r.density.medianPixelsPerTexel},
                                                                                  {QStringLiteral("pixels"), r.density.counted}}},
                                    {QStringLiteral("animation"), animationJson(r.animation)},
                                    {QStringLiteral("time_flicker"), timeFlickerJson(r.timeFlicker)},
                                    {QStringLiteral("flicker"), QJsonObject{{QStringLiteral("flips_pct"), flickerValue(r, r.flicker.flicker)},
                                                                            {QStringLiteral("worst_pair_pct"), flickerValue(r, r.flicker.worstPair)},
                                                                            {QStringLiteral("mean_change_pct"), flickerValue(r, r.flicker.meanChange)},
                                                                            {QStringLiteral("frames"), r.flicker.frames},
                                                                            {QStringLiteral("pixels"), r.flicker.pixels},
                                                                            {QStringLiteral("map_moves"), r.flicker.mapMoves}}}});
    }
    const QJsonObject json{{QStringLiteral("scene"), facts.scene},
                           {QStringLiteral("size"), QStringLiteral("%1x%2").arg(facts.size.width()).arg(facts.size.height())},
                           {QStringLiteral("frames"), facts.frames},
                           {QStringLiteral("min_frames"), facts.minFrames},
                           {QStringLiteral("warmup"), facts.warmup},
                           {QStringLiteral("renderer"), facts.renderer},
                           {QStringLiteral("machine"), facts.machine},
                           {QStringLiteral("area_samples_per_pixel"), facts.areaSamplesPerPixel},
                           {QStringLiteral("light_radius"), facts.lightRadius},
                           {QStringLiteral("area_noise_floor_pct"), facts.areaNoiseKnown() ? QJsonValue(100 * facts.areaNoiseFloor) : QJsonValue()},
                           {QStringLiteral("rays_per_second"), facts.raysPerSecond},
                           {QStringLiteral("reference_computations"), facts.referenceComputations},
                           {QStringLiteral("seconds"), facts.seconds},
                           {QStringLiteral("sweep"), facts.sweep},
                           {QStringLiteral("configurations"), facts.configurations},
                           {QStringLiteral("shard"), QStringLiteral("%1/%2").arg(facts.shard).arg(facts.shards)},
                           {QStringLiteral("parts"), facts.parts},
                           {QStringLiteral("recommendations"), recommendationsJson(rows)},
                           {QStringLiteral("rows"), jsonRows}};
    return QJsonDocument(json).toJson(QJsonDocument::Indented);
}

} // namespace shadowlab
