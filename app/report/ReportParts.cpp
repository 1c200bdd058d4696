#include "ReportParts.h"

#include "MessageText.h"
#include "ReportWriter.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace shadowlab {

namespace {

// More than any sweep has (the default has 58): a larger count is a damaged file, refused before
// anything is sized by it.
constexpr int kMostConfigurations = 100000;

// report.json's values, each read with the file and field named when it is missing or of
// another type.
class JsonReader {
public:
    JsonReader(QString file, QString context) : m_file(std::move(file)), m_context(std::move(context)) {}

    [[noreturn]] void fail(const QString& key, const QString& problem) const
    {
        throw ReportMergeError(QStringLiteral("%1: %2%3 %4; it is not a report.json that `shadowlab report` wrote, or one of an "
                                              "older version: measure it again")
                                   .arg(displayText(m_file), m_context, key, problem));
    }
    QJsonValue value(const QJsonObject& object, const QString& key) const
    {
        const QJsonValue v = object.value(key);
        if (v.isUndefined())
            fail(key, QStringLiteral("is missing"));
        return v;
    }
    double number(const QJsonObject& object, const QString& key) const
    {
        const QJsonValue v = value(object, key);
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            fail(key, QStringLiteral("is not a number"));
        return v.toDouble();
    }
    // A number, or null where the figure was not measured.
    double numberOrZero(const QJsonObject& object, const QString& key) const
    {
        return value(object, key).isNull() ? 0.0 : number(object, key);
    }
    // A share in percent, as a fraction.
    double percent(const QJsonObject& object, const QString& key) const
    {
        const double v = number(object, key);
        if (v < 0.0 || v > 100.0)
            fail(key, QStringLiteral("is not a percentage from 0 to 100"));
        return v / 100;
    }
    // A large count (texels, bytes), or -1 where it was not taken (null).
    std::int64_t bigCount(const QJsonObject& object, const QString& key) const
    {
        if (value(object, key).isNull())
            return -1;
        const double v = number(object, key);
        if (v < 0 || v > 1e18 || v != std::floor(v))
            fail(key, QStringLiteral("is not a count"));
        return std::int64_t(v);
    }
    int count(const QJsonObject& object, const QString& key) const
    {
        const double v = number(object, key);
        if (v < 0 || v > 1e9 || v != std::floor(v))
            fail(key, QStringLiteral("is not a count"));
        return int(v);
    }
    QString text(const QJsonObject& object, const QString& key) const
    {
        const QJsonValue v = value(object, key);
        if (!v.isString())
            fail(key, QStringLiteral("is not a string"));
        return v.toString();
    }
    bool flag(const QJsonObject& object, const QString& key) const
    {
        const QJsonValue v = value(object, key);
        if (!v.isBool())
            fail(key, QStringLiteral("is not true or false"));
        return v.toBool();
    }
    QJsonObject object(const QJsonObject& object, const QString& key) const
    {
        const QJsonValue v = value(object, key);
        if (!v.isObject())
            fail(key, QStringLiteral("is not an object"));
        return v.toObject();
    }
    JsonReader within(const QString& context) const { return JsonReader(m_file, m_context + context + QLatin1Char('.')); }

private:
    QString m_file;
    QString m_context;
};

SampleStats readStats(const JsonReader& json, const QJsonObject& object)
{
    SampleStats s;
    s.median = json.number(object, QStringLiteral("median_ms"));
    s.p10 = json.number(object, QStringLiteral("p10_ms"));
    s.p90 = json.number(object, QStringLiteral("p90_ms"));
    s.min = json.number(object, QStringLiteral("min_ms"));
    s.max = json.number(object, QStringLiteral("max_ms"));
    s.mean = json.number(object, QStringLiteral("mean_ms"));
    s.count = json.count(object, QStringLiteral("count"));
    return s;
}

ErrorMetrics readMetrics(const JsonReader& json, const QJsonObject& object)
{
    ErrorMetrics m;
    m.pixels = json.count(object, QStringLiteral("pixels"));
    m.misclassified = json.percent(object, QStringLiteral("misclassified_pct"));
    m.falseShadow = json.percent(object, QStringLiteral("false_shadow_pct"));
    m.falseLight = json.percent(object, QStringLiteral("false_light_pct"));
    m.mae = json.percent(object, QStringLiteral("mae_pct"));
    m.rmse = json.percent(object, QStringLiteral("rmse_pct"));
    return m;
}

FrameCounts readCounts(const JsonReader& json, const QJsonObject& object)
{
    FrameCounts c;
    const auto pass = [&](const QString& key) {
        const JsonReader p = json.within(key);
        const QJsonObject o = json.object(object, key);
        return PassCounts{.draws = p.count(o, QStringLiteral("draws")), .primitives = p.bigCount(o, QStringLiteral("primitives")),
                          .samples = p.bigCount(o, QStringLiteral("samples"))};
    };
    c.shadow = pass(QStringLiteral("shadow_pass"));
    c.lit = pass(QStringLiteral("lit_pass"));
    c.clearedTexels = json.bigCount(object, QStringLiteral("cleared_texels"));
    c.blurTexels = json.bigCount(object, QStringLiteral("blur_texels"));
    c.blurBytes = json.bigCount(object, QStringLiteral("blur_bytes"));
    c.mapBytes = json.bigCount(object, QStringLiteral("map_bytes"));
    // Reports from before shadow.cache have no copies.
    if (object.contains(QStringLiteral("cache_bytes"))) {
        c.copiedTexels = json.bigCount(object, QStringLiteral("copied_texels"));
        c.cacheBytes = json.bigCount(object, QStringLiteral("cache_bytes"));
    }
    c.tapsPerLookup = json.count(object, QStringLiteral("taps_per_lookup"));
    c.lookupFragments = json.bigCount(object, QStringLiteral("lookup_fragments"));
    return c;
}

ReportRow readRow(const JsonReader& file, const QJsonObject& object, const QDir& dir)
{
    ReportRow r;
    r.label = file.text(object, QStringLiteral("label"));
    const JsonReader json = file.within(QStringLiteral("rows['%1']").arg(r.label));
    r.sweepIndex = json.count(object, QStringLiteral("sweep_index"));
    r.defaults = json.flag(object, QStringLiteral("defaults"));
    r.tutorial = json.flag(object, QStringLiteral("tutorial"));
    r.renderer = json.text(object, QStringLiteral("renderer"));
    r.machine = json.text(object, QStringLiteral("machine"));
    r.light = json.text(object, QStringLiteral("light"));
    const QJsonValue settings = json.value(object, QStringLiteral("settings"));
    for (const QJsonValue& assignment : settings.toArray()) {
        if (!assignment.isString())
            json.fail(QStringLiteral("settings"), QStringLiteral("is not a list of key=value strings"));
        r.assignments << assignment.toString();
    }
    r.shadowPass = readStats(json.within(QStringLiteral("shadow_pass_wall")), json.object(object, QStringLiteral("shadow_pass_wall")));
    // Reports from before shadow.cache ran the pass every frame.
    const QJsonObject pass = json.object(object, QStringLiteral("shadow_pass_wall"));
    r.shadowPerFrame = pass.contains(QStringLiteral("per_frame_ms")) ? json.within(QStringLiteral("shadow_pass_wall")).number(pass, QStringLiteral("per_frame_ms"))
                                                                    : r.shadowPass.median;
    r.litPass = readStats(json.within(QStringLiteral("lit_pass_wall")), json.object(object, QStringLiteral("lit_pass_wall")));
    r.frame = readStats(json.within(QStringLiteral("frame_wall")), json.object(object, QStringLiteral("frame_wall")));
    r.counts = readCounts(json.within(QStringLiteral("counts")), json.object(object, QStringLiteral("counts")));
    // A report of the version before --cost weighed time.
    const std::optional<CostAxis> cost = object.contains(QStringLiteral("cost_axis")) ? costAxisFromKey(json.text(object, QStringLiteral("cost_axis")))
                                                                                       : std::optional(CostAxis::Time);
    if (!cost)
        json.fail(QStringLiteral("cost_axis"), QStringLiteral("is not time, taps or samples"));
    r.costAxis = *cost;
    r.accuracy.hard = readMetrics(json.within(QStringLiteral("hard_reference")), json.object(object, QStringLiteral("hard_reference")));
    r.accuracy.area = readMetrics(json.within(QStringLiteral("area_reference")), json.object(object, QStringLiteral("area_reference")));
    r.accuracy.ssim = json.number(object, QStringLiteral("mean_ssim"));
    if (r.accuracy.ssim < -1.0 || r.accuracy.ssim > 1.0)
        json.fail(QStringLiteral("mean_ssim"), QStringLiteral("is not from -1 to 1"));
    if (const QJsonValue area = object.value(QStringLiteral("area_mean_ssim")); !area.isUndefined() && !area.isNull()) {
        r.accuracy.areaSsim = json.number(object, QStringLiteral("area_mean_ssim"));
        if (*r.accuracy.areaSsim < -1.0 || *r.accuracy.areaSsim > 1.0)
            json.fail(QStringLiteral("area_mean_ssim"), QStringLiteral("is not from -1 to 1"));
    }
    r.accuracy.areaNoiseFloor = json.percent(object, QStringLiteral("area_noise_floor_pct"));
    r.paretoFront = json.flag(object, QStringLiteral("pareto_front"));
    r.areaFront = json.flag(object, QStringLiteral("area_pareto_front"));

    const QJsonObject density = json.object(object, QStringLiteral("texel_density"));
    const JsonReader d = json.within(QStringLiteral("texel_density"));
    r.density.counted = d.count(density, QStringLiteral("pixels"));
    r.density.fine = d.count(density, QStringLiteral("fine"));
    r.density.medianPixelsPerTexel = d.number(density, QStringLiteral("median_pixels_per_texel"));

    const QJsonObject flicker = json.object(object, QStringLiteral("flicker"));
    const JsonReader f = json.within(QStringLiteral("flicker"));
    r.flicker.frames = f.count(flicker, QStringLiteral("frames"));
    r.flicker.pixels = f.count(flicker, QStringLiteral("pixels"));
    r.flicker.mapMoves = f.count(flicker, QStringLiteral("map_moves"));
    const auto flickerShare = [&](const QString& key) { return f.value(flicker, key).isNull() ? 0.0 : f.percent(flicker, key); };
    r.flicker.flicker = flickerShare(QStringLiteral("flips_pct"));
    r.flicker.worstPair = flickerShare(QStringLiteral("worst_pair_pct"));
    r.flicker.meanChange = flickerShare(QStringLiteral("mean_change_pct"));

    const QJsonValue image = json.value(object, QStringLiteral("error_image"));
    if (!image.isNull()) {
        const QString name = json.text(object, QStringLiteral("error_image"));
        // Only the name the writer gives: an edited file cannot make this read elsewhere.
        if (name.contains(QLatin1String("..")) || QDir::isAbsolutePath(name))
            json.fail(QStringLiteral("error_image"), QStringLiteral("is not a file of the report's folder"));
        r.accuracy.hardErrors = QImage(dir.filePath(name), "PNG");   // only through the decoder the writer used
        if (r.accuracy.hardErrors.isNull())
            throw ReportMergeError(QStringLiteral("%1 cannot be read as an image: copy the report's whole folder, errors/ with it")
                                       .arg(displayText(dir.filePath(name))));
    }
    return r;
}

QString partName(const ReportPart& part)
{
    return part.facts.shards > 1
               ? QStringLiteral("%1 (share %2/%3)").arg(displayText(part.directory), QString::number(part.facts.shard), QString::number(part.facts.shards))
               : displayText(part.directory);
}

// What two parts of different sweeps differ in, as a reader would check it first.
QString sweepDifference(const ReportFacts& a, const ReportFacts& b)
{
    if (a.scene != b.scene)
        return QStringLiteral("scene %1 against %2").arg(displayText(a.scene), displayText(b.scene));
    if (a.size != b.size)
        return QStringLiteral("size %1x%2 against %3x%4").arg(a.size.width()).arg(a.size.height()).arg(b.size.width()).arg(b.size.height());
    if (a.configurations != b.configurations)
        return QStringLiteral("%1 configurations against %2").arg(a.configurations).arg(b.configurations);
    const auto option = [](const QString& name, auto x, auto y) { return QStringLiteral("%1 %2 against %3").arg(name).arg(x).arg(y); };
    if (a.frames != b.frames)
        return option(QStringLiteral("--frames"), a.frames, b.frames);
    if (a.minFrames != b.minFrames)
        return option(QStringLiteral("--min-frames"), a.minFrames, b.minFrames);
    if (a.warmup != b.warmup)
        return option(QStringLiteral("--warmup"), a.warmup, b.warmup);
    if (a.areaSamplesPerPixel != b.areaSamplesPerPixel)
        return option(QStringLiteral("rays a pixel (--area-samples squared)"), a.areaSamplesPerPixel, b.areaSamplesPerPixel);
    return QStringLiteral("the sweep's configurations, their settings (--sweep, --set, --settings, --preset) or --flicker-frames");
}

} // namespace

std::optional<std::pair<int, int>> parseShare(const QString& text)
{
    const QStringList parts = text.split(QLatin1Char('/'));
    bool okK = false, okN = false;
    const int k = parts.value(0).trimmed().toInt(&okK), n = parts.value(1).trimmed().toInt(&okN);
    if (parts.size() != 2 || !okK || !okN || n < 1 || k < 1 || k > n)
        return std::nullopt;
    return std::pair(k, n);
}

ReportPart readReportPart(const QString& directory)
{
    const QFileInfo folder(directory);
    if (!folder.exists())
        throw ReportMergeError(QStringLiteral("%1: no such folder; give folders that `shadowlab report --out` wrote").arg(displayText(directory)));
    if (!folder.isDir())
        throw ReportMergeError(QStringLiteral("%1: is a file, not a report's folder; give the folder it is in").arg(displayText(directory)));
    const QDir dir(directory);
    const QString path = dir.filePath(QStringLiteral("report.json"));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw ReportMergeError(QStringLiteral("%1: cannot be read (%2); give folders that `shadowlab report --out` wrote")
                                   .arg(displayText(path), file.errorString()));
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &error);
    if (document.isNull())
        throw ReportMergeError(QStringLiteral("%1: is not JSON (%2 at byte %3)").arg(displayText(path), error.errorString(), QString::number(error.offset)));
    if (!document.isObject())
        throw ReportMergeError(QStringLiteral("%1: is JSON but not a report (no object at its top); give folders that `shadowlab report --out` wrote")
                                   .arg(displayText(path)));
    const QJsonObject top = document.object();
    const JsonReader json(path, QString());

    ReportPart part;
    part.directory = directory;
    ReportFacts& f = part.facts;
    f.scene = json.text(top, QStringLiteral("scene"));
    const QStringList size = json.text(top, QStringLiteral("size")).split(QLatin1Char('x'));
    f.size = QSize(size.value(0).toInt(), size.value(1).toInt());
    if (size.size() != 2 || f.size.isEmpty())
        json.fail(QStringLiteral("size"), QStringLiteral("is not WxH"));
    f.frames = json.count(top, QStringLiteral("frames"));
    f.minFrames = json.count(top, QStringLiteral("min_frames"));
    f.warmup = json.count(top, QStringLiteral("warmup"));
    f.renderer = json.text(top, QStringLiteral("renderer"));
    f.machine = json.text(top, QStringLiteral("machine"));
    f.areaSamplesPerPixel = json.count(top, QStringLiteral("area_samples_per_pixel"));
    f.lightRadius = json.number(top, QStringLiteral("light_radius"));
    f.areaNoiseFloor = json.numberOrZero(top, QStringLiteral("area_noise_floor_pct")) / 100;
    f.raysPerSecond = json.number(top, QStringLiteral("rays_per_second"));
    f.referenceComputations = json.count(top, QStringLiteral("reference_computations"));
    f.seconds = json.number(top, QStringLiteral("seconds"));
    f.sweep = json.text(top, QStringLiteral("sweep"));
    f.configurations = json.count(top, QStringLiteral("configurations"));
    if (f.configurations < 1 || f.configurations > kMostConfigurations)
        json.fail(QStringLiteral("configurations"), QStringLiteral("is not between 1 and %1").arg(kMostConfigurations));
    const std::optional<std::pair<int, int>> share = parseShare(json.text(top, QStringLiteral("shard")));
    if (!share)
        json.fail(QStringLiteral("shard"), QStringLiteral("is not K/N"));
    std::tie(f.shard, f.shards) = *share;
    f.parts = json.count(top, QStringLiteral("parts"));
    const QJsonValue rows = json.value(top, QStringLiteral("rows"));
    if (!rows.isArray())
        json.fail(QStringLiteral("rows"), QStringLiteral("is not a list"));
    if (rows.toArray().isEmpty())
        json.fail(QStringLiteral("rows"), QStringLiteral("is empty"));
    if (rows.toArray().size() > f.configurations * qsizetype(f.parts))
        json.fail(QStringLiteral("rows"), QStringLiteral("holds more rows than the sweep has configurations"));
    for (const QJsonValue& row : rows.toArray()) {
        if (!row.isObject())
            json.fail(QStringLiteral("rows"), QStringLiteral("holds something other than rows"));
        part.rows.push_back(readRow(json, row.toObject(), dir));
        if (part.rows.back().sweepIndex >= f.configurations)
            json.fail(QStringLiteral("rows"), QStringLiteral("holds a configuration past the sweep's %1").arg(f.configurations));
    }
    return part;
}

namespace {

// Refuses a merge that leaves configurations of the sweep unmeasured, naming them and, where
// every part was cut alike, the shares to add.
void refuseMissing(const std::vector<ReportPart>& parts, const std::map<std::pair<int, QString>, const ReportPart*>& measured)
{
    const ReportPart& first = parts.front();
    std::vector<bool> found(std::size_t(first.facts.configurations), false);
    for (const auto& entry : measured)
        found[std::size_t(entry.first.first)] = true;
    std::vector<int> missing;
    for (int i = 0; i < first.facts.configurations; ++i) {
        if (!found[std::size_t(i)])
            missing.push_back(i);
    }
    if (missing.empty())
        return;
    // Said as the shares to add, where every part was cut into the same number of shares.
    const int shards = first.facts.shards;
    const bool sameCut = std::all_of(parts.begin(), parts.end(), [&](const ReportPart& p) { return p.facts.shards == shards; });
    QStringList absent;
    std::set<int> shares;
    for (int i : missing) {
        if (absent.size() < 12)
            absent << QString::number(i + 1);
        shares.insert(i % shards + 1);
    }
    QString hint;
    if (sameCut && shards > 1) {
        QStringList named;
        for (int k : shares)
            named << QStringLiteral("--shard %1/%2").arg(k).arg(shards);
        hint = QStringLiteral(": add the report of %1").arg(named.join(QStringLiteral(", ")));
    }
    throw ReportMergeError(QStringLiteral("%1 of the sweep's %2 configurations %3 in none of the reports given (%4 %5)%6")
                               .arg(missing.size())
                               .arg(first.facts.configurations)
                               .arg(missing.size() == 1 ? QStringLiteral("is") : QStringLiteral("are"),
                                    missing.size() == 1 ? QStringLiteral("number") : QStringLiteral("numbers"),
                                    absent.join(QStringLiteral(", ")) + (missing.size() > 12 ? QStringLiteral(", …") : QString()), hint));
}

} // namespace

MergedReport mergeReportParts(const std::vector<ReportPart>& parts)
{
    if (parts.empty())
        throw ReportMergeError(QStringLiteral("give the report folders to merge"));
    const ReportPart& first = parts.front();
    for (const ReportPart& part : parts) {
        if (part.facts.sweep != first.facts.sweep || part.facts.configurations != first.facts.configurations)
            throw ReportMergeError(QStringLiteral("%1 and %2 measured different sweeps (%3): merge only shares and reports of one sweep, "
                                                  "made with the same --scene, --size, --sweep, settings, --frames, --min-frames, --warmup, --area-samples and "
                                                  "--flicker-frames")
                                       .arg(partName(first), partName(part), sweepDifference(first.facts, part.facts)));
    }
    // Each configuration once per machine: a second copy is the same share given twice.
    std::map<std::pair<int, QString>, const ReportPart*> measured;
    for (const ReportPart& part : parts) {
        for (const ReportRow& row : part.rows) {
            const auto [at, fresh] = measured.emplace(std::pair(row.sweepIndex, timedOn(row)), &part);
            if (!fresh)
                throw ReportMergeError(QStringLiteral("%1 and %2 both hold '%3', measured on the same machine: give each share once, all of one "
                                                      "cut (--shard K/N with the same N), or a whole report alone")
                                           .arg(partName(*at->second), partName(part), row.label));
        }
    }
    refuseMissing(parts, measured);

    MergedReport merged;
    ReportFacts& f = merged.facts;
    f = first.facts;
    f.shard = f.shards = 1;
    f.parts = 0;
    f.seconds = 0.0;
    f.referenceComputations = 0;
    f.areaNoiseFloor = 0.0;
    f.raysPerSecond = 0.0;
    QStringList renderers, machines;
    for (const ReportPart& part : parts) {
        f.parts += part.facts.parts;
        f.seconds += part.facts.seconds;
        f.referenceComputations += part.facts.referenceComputations;
        f.areaNoiseFloor = std::max(f.areaNoiseFloor, part.facts.areaNoiseFloor);
        f.raysPerSecond = std::max(f.raysPerSecond, part.facts.raysPerSecond);
        if (!renderers.contains(part.facts.renderer))
            renderers << part.facts.renderer;
        if (!machines.contains(part.facts.machine))
            machines << part.facts.machine;
        merged.rows.insert(merged.rows.end(), part.rows.begin(), part.rows.end());
    }
    f.renderer = renderers.join(QStringLiteral("; "));
    f.machine = machines.join(QStringLiteral("; "));
    std::stable_sort(merged.rows.begin(), merged.rows.end(), [](const ReportRow& a, const ReportRow& b) { return a.sweepIndex < b.sweepIndex; });
    for (const ReportRow& r : merged.rows) {
        if (r.costAxis != merged.rows.front().costAxis)
            throw ReportMergeError(QStringLiteral("the reports weigh cost differently (%1 and %2): measure them with the same --cost")
                                       .arg(costAxisKey(merged.rows.front().costAxis), costAxisKey(r.costAxis)));
    }
    markParetoFronts(merged.rows);

    if (severalMachines(merged.rows)) {
        merged.notes << QStringLiteral("the rows were measured on %1 renderers or machines: each row's times are compared only with rows of "
                                       "its own machine, each machine has its own front, and the renderer column says whose a row is")
                            .arg(std::max(renderers.size(), machines.size()));
        std::map<QString, int> perMachine;
        for (const ReportRow& r : merged.rows)
            ++perMachine[timedOn(r)];
        for (const auto& [machine, rows] : perMachine) {
            if (rows < f.configurations)
                merged.notes << QStringLiteral("%1 measured %2 of the %3 configurations").arg(machine).arg(rows).arg(f.configurations);
        }
    }
    return merged;
}

} // namespace shadowlab
