#include "ReportAnalysis.h"

#include "ErrorNoise.h"
#include "FrameStatsText.h"
#include "SettingsKeys.h"

#include <embree3/rtcore_config.h>

#include <QFile>
#include <QRegularExpression>
#include <QSysInfo>
#include <QThread>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <limits>

namespace shadowlab {

std::size_t AnimatedError::worst() const
{
    return std::size_t(std::max_element(misclassified.begin(), misclassified.end()) - misclassified.begin());
}

double mean(const std::vector<double>& values)
{
    return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

namespace {

const ErrorMetrics& metrics(const ReportRow& row, ErrorAxis axis)
{
    return axis == ErrorAxis::Misclassified ? row.accuracy.hard : row.accuracy.area;
}

QString msText(double ms)
{
    return QStringLiteral("%1 ms").arg(ms, 0, 'f', ms < 10.0 ? 2 : 1);
}

bool clearlyFaster(const SampleStats& a, const SampleStats& b)
{
    return a.p90 < b.p10;
}

bool beats(const ReportRow& b, const ReportRow& a, ErrorAxis axis)
{
    return comparable(a, b) && clearlyFaster(costOf(b), costOf(a)) && clearlyFewer(errorPixels(b, axis), errorPixels(a, axis));
}

void markFront(std::vector<ReportRow>& rows, ErrorAxis axis, bool ReportRow::*flag)
{
    std::vector<bool> wrong;
    for (const ReportRow& r : rows)
        wrong.push_back(!visiblyWrong(r).isEmpty());
    // A row without a cost on the axis (a count not taken) is nowhere on it.
    std::vector<bool> costed;
    for (const ReportRow& r : rows)
        costed.push_back(std::isfinite(costOf(r).median));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ReportRow& a = rows[i];
        bool beaten = false;
        for (std::size_t j = 0; j < rows.size() && !beaten; ++j)
            beaten = !wrong[j] && costed[j] && beats(rows[j], a, axis);
        a.*flag = measuredPixels(a, axis) > 0 && !wrong[i] && costed[i] && !beaten;
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

SampleStats costOf(const ReportRow& row)
{
    if (isTime(row.costAxis))
        return row.frame;
    const std::int64_t count = row.costAxis == CostAxis::Taps ? row.counts.taps() : row.counts.shadow.samples;
    SampleStats s;
    if (count < 0) {
        // Not counted (a report of an older version merged in): nowhere on the axis.
        s.median = s.p10 = s.p90 = s.mean = std::numeric_limits<double>::quiet_NaN();
        return s;
    }
    s.count = 1;
    s.median = s.mean = double(count);
    s.p10 = double(count) * (1.0 - kCountBand);
    s.p90 = double(count) * (1.0 + kCountBand);
    return s;
}

QString costText(const ReportRow& row, double cost)
{
    if (!std::isfinite(cost))
        return QStringLiteral("n/a");
    switch (row.costAxis) {
    case CostAxis::Time: return msText(cost);
    case CostAxis::Taps: return countText(std::int64_t(std::llround(cost))) + QStringLiteral(" taps");
    case CostAxis::ShadowSamples: return countText(std::int64_t(std::llround(cost))) + QStringLiteral(" shadow-pass samples");
    }
    return {};
}

QString costAxisTitle(CostAxis axis)
{
    switch (axis) {
    case CostAxis::Time: return QStringLiteral("frame time, shadow pass every frame (ms, log scale; median, bar p10–p90)");
    case CostAxis::Taps: return QStringLiteral("shadow taps a frame, the same on any GPU (log scale)");
    case CostAxis::ShadowSamples: return QStringLiteral("shadow-pass samples a pass, the same on any GPU (log scale)");
    }
    return {};
}

QString costAxisKey(CostAxis axis)
{
    switch (axis) {
    case CostAxis::Time: return QStringLiteral("time");
    case CostAxis::Taps: return QStringLiteral("taps");
    case CostAxis::ShadowSamples: return QStringLiteral("samples");
    }
    return {};
}

std::optional<CostAxis> costAxisFromKey(const QString& key)
{
    for (CostAxis axis : {CostAxis::Time, CostAxis::Taps, CostAxis::ShadowSamples}) {
        if (costAxisKey(axis) == key)
            return axis;
    }
    return std::nullopt;
}

QString timedOn(const ReportRow& row)
{
    // What decides a frame's time: the renderer, and the CPU and its cores (a software
    // rasteriser's threads; a scheduler's allocation). Memory size and software versions are
    // facts of the run, not a reason to keep two alike nodes' rows apart.
    static const QRegularExpression cpuAndCores(QStringLiteral("^.*?, \\d+ cores"));
    const QRegularExpressionMatch match = cpuAndCores.match(row.machine);
    return row.renderer + QStringLiteral(" (") + (match.hasMatch() ? match.captured(0) : row.machine) + u')';
}

bool comparable(const ReportRow& a, const ReportRow& b)
{
    // Counts are the same on any GPU: only times stay with their machine.
    return a.light == b.light && (!isTime(a.costAxis) || timedOn(a) == timedOn(b));
}

bool severalMachines(const std::vector<ReportRow>& rows)
{
    return std::any_of(rows.begin(), rows.end(), [&](const ReportRow& r) { return timedOn(r) != timedOn(rows.front()); });
}

QString lightOf(const ReportRow& row, const std::vector<ReportRow>& rows)
{
    // Times stay with their machine; counts, the same on any GPU, do not (comparable()).
    return isTime(row.costAxis) && severalMachines(rows) ? QStringLiteral("%1, on %2").arg(row.light, timedOn(row)) : row.light;
}

QStringList lightsOf(const std::vector<ReportRow>& rows)
{
    QStringList lights;
    for (const ReportRow& r : rows) {
        if (const QString light = lightOf(r, rows); !lights.contains(light))
            lights << light;
    }
    return lights;
}

std::vector<const ReportRow*> frontOf(const std::vector<ReportRow>& rows, const QString& light, ErrorAxis axis)
{
    std::vector<const ReportRow*> front;
    for (const ReportRow& r : rows) {
        if (lightOf(r, rows) == light && (axis == ErrorAxis::Misclassified ? r.paretoFront : r.areaFront))
            front.push_back(&r);
    }
    std::stable_sort(front.begin(), front.end(), [](const ReportRow* a, const ReportRow* b) { return costOf(*a).median < costOf(*b).median; });
    return front;
}

double dssim(const ReportRow& r)
{
    return 1.0 - r.accuracy.ssim;
}

QString visiblyWrong(const ReportRow& r)
{
    return visiblyWrong(r.accuracy);
}

QString visiblyWrong(const AccuracyResult& a)
{
    const double hard = 1.0 - a.ssim;
    const std::optional<double> area = a.areaSsim ? std::optional(1.0 - *a.areaSsim) : std::nullopt;
    if (hard <= kVisibleDssim || (area && *area <= kVisibleDssim))
        return {};
    const QString against = area ? QStringLiteral("DSSIM %1 against the hard light's picture and %2 against the area light's")
                                       .arg(hard, 0, 'f', 4)
                                       .arg(*area, 0, 'f', 4)
                                 : QStringLiteral("DSSIM %1 against the reference's picture").arg(hard, 0, 'f', 4);
    return QStringLiteral("visibly wrong: %1, over %2 (acne or a moiré of partial shadow that misclassified pixels miss)")
        .arg(against)
        .arg(kVisibleDssim);
}

namespace {

bool tiedInTime(const ReportRow& a, const ReportRow& b)
{
    return !clearlyFaster(costOf(a), costOf(b)) && !clearlyFaster(costOf(b), costOf(a));
}

bool tiedInError(const ReportRow& a, const ReportRow& b, ErrorAxis axis)
{
    return !clearlyFewer(errorPixels(a, axis), errorPixels(b, axis)) && !clearlyFewer(errorPixels(b, axis), errorPixels(a, axis));
}


// A share in percent with the digits its size needs: 0.0031 %, 0.052 %, 1.4 %.
QString shareText(double fraction)
{
    const double v = 100.0 * fraction;
    const int decimals = v <= 0.0 ? 0 : std::clamp(1 - int(std::floor(std::log10(v))), 0, 4);
    return QStringLiteral("%1 %").arg(v, 0, 'f', decimals);
}

QString errorText(const ReportRow& r, ErrorAxis axis)
{
    const double pixels = errorPixels(r, axis);
    return axis == ErrorAxis::Misclassified
               ? QStringLiteral("%1 misclassified (%2 ± %3 px)").arg(shareText(errorShare(r, axis))).arg(pixels, 0, 'f', 0).arg(errorNoisePixels(pixels), 0, 'f', 0)
               : QStringLiteral("area MAE %1 ± %2").arg(shareText(errorShare(r, axis)), shareText(errorNoisePixels(pixels) / std::max(1, measuredPixels(r, axis))));
}

// Of `candidates`, those tied with the best on `axis`; the pick is the fastest of them.
Recommendation mostAccurate(std::vector<const ReportRow*> candidates, ErrorAxis axis, Recommendation::Kind kind)
{
    Recommendation pick;
    pick.kind = kind;
    if (candidates.empty())
        return pick;
    const ReportRow* best = *std::min_element(candidates.begin(), candidates.end(), [&](const ReportRow* a, const ReportRow* b) {
        return errorPixels(*a, axis) < errorPixels(*b, axis);
    });
    std::vector<const ReportRow*> tied;
    for (const ReportRow* r : candidates) {
        if (tiedInError(*r, *best, axis))
            tied.push_back(r);
    }
    std::stable_sort(tied.begin(), tied.end(), [](const ReportRow* a, const ReportRow* b) { return costOf(*a).median < costOf(*b).median; });
    pick.row = tied.front();
    pick.ties.assign(tied.begin() + 1, tied.end());
    return pick;
}

} // namespace

std::vector<const ReportRow*> visiblyWrongRows(const std::vector<ReportRow>& rows, const QString& light)
{
    std::vector<const ReportRow*> wrong;
    for (const ReportRow& r : rows) {
        if (lightOf(r, rows) == light && !visiblyWrong(r).isEmpty())
            wrong.push_back(&r);
    }
    return wrong;
}

std::vector<Recommendation> recommend(const std::vector<ReportRow>& rows, const QString& light)
{
    std::vector<const ReportRow*> clean;
    for (const ReportRow& r : rows) {
        if (lightOf(r, rows) == light && measuredPixels(r, ErrorAxis::Misclassified) > 0 && visiblyWrong(r).isEmpty() && std::isfinite(costOf(r).median))
            clean.push_back(&r);
    }
    if (clean.empty()) {
        // Every picture visibly wrong (one map over a whole city at a small size): still an
        // answer, the least wrong, said as such.
        const ReportRow* least = nullptr;
        const auto pictureError = [](const ReportRow& r) {
            return std::min(dssim(r), r.accuracy.areaSsim ? 1.0 - *r.accuracy.areaSsim : dssim(r));
        };
        for (const ReportRow& r : rows) {
            if (lightOf(r, rows) == light && measuredPixels(r, ErrorAxis::Misclassified) > 0 && std::isfinite(costOf(r).median)
                && (!least || pictureError(r) < pictureError(*least)))
                least = &r;
        }
        if (!least)
            return {};
        // Pictures within a twentieth of the least wrong one look as wrong: of those, the fastest.
        const double within = pictureError(*least) + std::max(0.0005, 0.05 * pictureError(*least));
        Recommendation pick;
        pick.kind = Recommendation::Kind::LeastWrong;
        pick.row = least;
        for (const ReportRow& r : rows) {
            if (lightOf(r, rows) == light && measuredPixels(r, ErrorAxis::Misclassified) > 0 && pictureError(r) <= within
                && costOf(r).median < costOf(*pick.row).median)
                pick.row = &r;
        }
        return {pick};
    }
    if (clean.size() == 1) {
        Recommendation only;
        only.kind = Recommendation::Kind::Only;
        only.row = clean.front();
        return {only};
    }
    std::vector<Recommendation> picks;
    // The cheapest: of the rows no other is clearly faster than, the most accurate; its ties
    // are as fast and as accurate. (Ties in time are not transitive: a row tied with the
    // fastest may still be clearly slower than a third.)
    std::vector<const ReportRow*> asFast;
    for (const ReportRow* r : clean) {
        if (std::none_of(clean.begin(), clean.end(), [&](const ReportRow* q) { return clearlyFaster(costOf(*q), costOf(*r)); }))
            asFast.push_back(r);
    }
    Recommendation cheapest = mostAccurate(asFast, ErrorAxis::Misclassified, Recommendation::Kind::Cheapest);
    std::erase_if(cheapest.ties, [&](const ReportRow* r) { return !tiedInTime(*r, *cheapest.row); });
    picks.push_back(cheapest);
    // The most accurate within the budget.
    const double budget = kRecommendationBudget * costOf(*cheapest.row).median;
    std::vector<const ReportRow*> affordable;
    for (const ReportRow* r : clean) {
        if (costOf(*r).median <= budget)
            affordable.push_back(r);
    }
    Recommendation accurate = mostAccurate(affordable, ErrorAxis::Misclassified, Recommendation::Kind::MostAccurate);
    accurate.budget = budget;
    // Nothing affordable clearly more accurate than the cheapest: the cheapest it is (ties are
    // not transitive, so the best's tie set may hold another row as good as the cheapest).
    if (!clearlyFewer(errorPixels(*accurate.row, ErrorAxis::Misclassified), errorPixels(*cheapest.row, ErrorAxis::Misclassified))) {
        accurate.row = cheapest.row;
        accurate.ties = cheapest.ties;
        accurate.sameAsCheapest = true;
    }
    picks.push_back(accurate);
    // The closest to the area light, at any cost.
    std::vector<const ReportRow*> traced;
    for (const ReportRow* r : clean) {
        if (measuredPixels(*r, ErrorAxis::AreaMae) > 0)
            traced.push_back(r);
    }
    if (!traced.empty())
        picks.push_back(mostAccurate(traced, ErrorAxis::AreaMae, Recommendation::Kind::ClosestToArea));
    return picks;
}

QString Recommendation::title() const
{
    switch (kind) {
    case Kind::Cheapest:
        return QStringLiteral("Cheapest with nothing visibly wrong");
    case Kind::MostAccurate:
        return QStringLiteral("Most accurate within %1 (%2× the cheapest)").arg(costText(*row, budget)).arg(kRecommendationBudget);
    case Kind::ClosestToArea:
        return QStringLiteral("Closest to the area light");
    case Kind::Only:
        return QStringLiteral("The one configuration with nothing visibly wrong");
    case Kind::LeastWrong:
        return QStringLiteral("Least wrong, as every picture here is visibly wrong");
    }
    return {};
}

QString Recommendation::reason() const
{
    if (row == nullptr)
        return {};
    const ErrorAxis axis = kind == Kind::ClosestToArea ? ErrorAxis::AreaMae : ErrorAxis::Misclassified;
    QString text;
    switch (kind) {
    case Kind::Cheapest:
        text = QStringLiteral("%1 a frame%2: of the rows whose picture is not visibly wrong and that no such row is clearly %3 than, "
                              "the most accurate; %4")
                   .arg(costText(*row, costOf(*row).median))
                   .arg(isTime(row->costAxis) ? QStringLiteral(" (p10–p90 %1–%2 ms)")
                                                    .arg(row->frame.p10, 0, 'f', row->frame.p10 < 10.0 ? 2 : 1)
                                                    .arg(row->frame.p90, 0, 'f', row->frame.p90 < 10.0 ? 2 : 1)
                                              : QString())
                   .arg(isTime(row->costAxis) ? QStringLiteral("faster") : QStringLiteral("cheaper"))
                   .arg(errorText(*row, axis));
        break;
    case Kind::MostAccurate:
        text = sameAsCheapest ? QStringLiteral("the cheapest again: no row within %1 a frame is clearly more accurate (%2)")
                                    .arg(costText(*row, budget), errorText(*row, axis))
                              : QStringLiteral("%1, the fewest of the rows that take at most %2 a frame; %3 a frame")
                                    .arg(errorText(*row, axis), costText(*row, budget), costText(*row, costOf(*row).median));
        break;
    case Kind::ClosestToArea:
        text = QStringLiteral("%1, the smallest at any cost; %2 a frame").arg(errorText(*row, axis), costText(*row, costOf(*row).median));
        break;
    case Kind::Only:
        text = QStringLiteral("%1 a frame, %2; the others under this light are visibly wrong, or there are none")
                   .arg(costText(*row, costOf(*row).median), errorText(*row, axis));
        break;
    case Kind::LeastWrong:
        text = QStringLiteral("DSSIM %1 against the hard light's picture%2, the least of all within a twentieth, and of those the "
                              "%5; %3 a frame, %4. A map's texel is larger than a pixel here (the table's \"texels ≤ 1 px\"): "
                              "a larger image, cascades or a virtual map (--sweep cascades, --sweep virtual) may give a clean one")
                   .arg(dssim(*row), 0, 'f', 4)
                   .arg(row->accuracy.areaSsim ? QStringLiteral(" and %1 against the area light's").arg(1.0 - *row->accuracy.areaSsim, 0, 'f', 4) : QString())
                   .arg(costText(*row, costOf(*row).median), errorText(*row, axis))
                   .arg(isTime(row->costAxis) ? QStringLiteral("fastest") : QStringLiteral("cheapest"));
        break;
    }
    if (!ties.empty()) {
        // The fastest few in figures; the rest by count (report.json lists every tie).
        constexpr std::size_t kNamed = 4;
        QStringList names;
        for (std::size_t i = 0; i < std::min(ties.size(), kNamed); ++i)
            names << QStringLiteral("%1 (%2, %3)").arg(ties[i]->label, costText(*ties[i], costOf(*ties[i]).median), errorText(*ties[i], axis));
        if (ties.size() > kNamed)
            names << QStringLiteral("and %1 more, each %2").arg(ties.size() - kNamed).arg(isTime(row->costAxis) ? QStringLiteral("slower") : QStringLiteral("dearer"));
        text += (kind == Kind::Cheapest ? (isTime(row->costAxis) ? QStringLiteral(". Ties, as fast and as accurate within their noise: ")
                                                                 : QStringLiteral(". Ties, as cheap and as accurate within their noise: "))
                                        : QStringLiteral(". Ties, as accurate within their noise: "))
              + names.join(QStringLiteral("; "));
    }
    return text + u'.';
}

double areaNoisePercent(const ReportRow& r)
{
    return 100.0 * errorNoisePixels(errorPixels(r, ErrorAxis::AreaMae)) / std::max(1, measuredPixels(r, ErrorAxis::AreaMae));
}

QString lightDescription(const Settings& settings)
{
    // Six significant digits: a model's fitted light reads (-104.289, 243.34, -69.5257), not to
    // fifteen digits, and two lights a sweep sets apart still differ.
    auto vec = [&](const glm::dvec3& v) { return QStringLiteral("(%1, %2, %3)").arg(v.x, 0, 'g', 6).arg(v.y, 0, 'g', 6).arg(v.z, 0, 'g', 6); };
    return QStringLiteral("%1 light at %2 towards %3")
        .arg(toString(settings.light.projection), vec(settings.light.position), vec(settings.light.target));
}

QImage zoomOnErrors(const QImage& errors, int factor)
{
    if (errors.isNull() || factor < 1)
        return {};
    const QImage image = errors.convertToFormat(QImage::Format_RGB32);
    const int w = image.width(), h = image.height();
    // Summed-area table of misclassified pixels (coloured; everything else is grey).
    std::vector<int> sum(std::size_t(w + 1) * std::size_t(h + 1), 0);
    auto at = [&](int x, int y) -> int& { return sum[std::size_t(y) * std::size_t(w + 1) + std::size_t(x)]; };
    for (int y = 0; y < h; ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < w; ++x) {
            const bool error = qRed(line[x]) != qGreen(line[x]) || qGreen(line[x]) != qBlue(line[x]);
            at(x + 1, y + 1) = at(x, y + 1) + at(x + 1, y) - at(x, y) + (error ? 1 : 0);
        }
    }
    if (at(w, h) == 0)
        return {};
    const int cw = std::max(1, w / factor), ch = std::max(1, h / factor);
    const int step = std::max(1, std::min(cw, ch) / 8);
    int bestX = 0, bestY = 0, best = -1;
    for (int y = 0; y + ch <= h; y += step) {
        for (int x = 0; x + cw <= w; x += step) {
            const int count = at(x + cw, y + ch) - at(x, y + ch) - at(x + cw, y) + at(x, y);
            if (count > best) {
                best = count;
                bestX = x;
                bestY = y;
            }
        }
    }
    return image.copy(bestX, bestY, cw, ch).scaled(cw * factor, ch * factor, Qt::IgnoreAspectRatio, Qt::FastTransformation);
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

} // namespace shadowlab
