#include "ReportSweep.h"

#include "InputFile.h"
#include "MessageText.h"
#include "MomentMath.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"

#include <glm/vec3.hpp>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <algorithm>

namespace shadowlab {

namespace {

// Every technique's variations, as its row of the technique table lists them.
std::vector<SweepEntry> filterSweep()
{
    std::vector<SweepEntry> s;
    for (const ShadowTechnique& technique : shadowTechniques()) {
        for (const TechniqueVariation& variation : technique.sweep)
            s.push_back({variation.label, variation.assignments});
    }
    return s;
}

// Every moment technique of the table at its defaults, over blur widths and both moments
// formats, and those that reduce light bleeding once more without it.
std::vector<SweepEntry> filterableSweep()
{
    std::vector<SweepEntry> s;
    for (const ShadowTechnique& technique : shadowTechniques()) {
        if (!isMomentTechnique(technique.mode))
            continue;
        const QString mode = QStringLiteral("filter.mode=") + technique.key;
        for (const char* bits : {"32", "16"}) {
            for (const char* blur : {"0", "3", "7"})
                s.push_back({QStringLiteral("%1 %2-bit blur %3").arg(technique.key, QLatin1String(bits), QLatin1String(blur)),
                             {mode, QStringLiteral("moments.format=%1").arg(QLatin1String(bits)), QStringLiteral("moments.blur=%1").arg(QLatin1String(blur))}});
        }
        if (technique.parameters.contains(QStringLiteral("filter.bleeding")))
            s.push_back({QStringLiteral("%1 without bleeding reduction").arg(technique.key), {mode, QStringLiteral("filter.bleeding=0")}});
    }
    return s;
}

std::vector<SweepEntry> resolutionSweep()
{
    std::vector<SweepEntry> s;
    for (int size : {256, 512, 1024, 2048, 4096})
        s.push_back({QStringLiteral("map %1").arg(size), {QStringLiteral("map.size=%1").arg(size)}});
    for (int size : {512, 4096})
        s.push_back({QStringLiteral("map %1 hard").arg(size), {QStringLiteral("map.size=%1").arg(size), QStringLiteral("filter.mode=hard")}});
    return s;
}

std::vector<SweepEntry> biasSweep()
{
    std::vector<SweepEntry> s;
    // The classic forms draw front faces and the floor, with one bias for every tap, where the
    // bias alone must hold acne off: the slope/min grid in world units, texels, depth units,
    // culling and polygon offset.
    const auto classic = [](QStringList assignments) {
        return QStringList{QStringLiteral("bias.footprint=false"), QStringLiteral("bias.skip_floors=false")} + assignments;
    };
    // The grid is in texels of the map, so that it spans acne to peter panning alike on a 1-unit
    // cube and a 250-unit model (a world-unit grid of 0 to 0.2 was all acne on the latter).
    for (const char* slope : {"0", "1", "3", "8"}) {
        for (const char* min : {"0", "0.25", "0.5", "1.5"})
            s.push_back({QStringLiteral("bias %1/%2 texels").arg(QLatin1String(slope), QLatin1String(min)),
                         classic({QStringLiteral("bias.cull_front=false"), QStringLiteral("bias.space=texel"), QStringLiteral("bias.slope=%1").arg(QLatin1String(slope)),
                                  QStringLiteral("bias.min=%1").arg(QLatin1String(min))})});
    }
    s.push_back({QStringLiteral("bias 0.02/0.001 depth units"), classic({QStringLiteral("bias.cull_front=false"), QStringLiteral("bias.space=depth"),
                                                                          QStringLiteral("bias.slope=0.02"), QStringLiteral("bias.min=0.001")})});
    s.push_back({QStringLiteral("cull front, no bias"), classic({QStringLiteral("bias.cull_front=true"), QStringLiteral("bias.slope=0"),
                                                                  QStringLiteral("bias.min=0")})});
    s.push_back({QStringLiteral("polygon offset 2/4"), classic({QStringLiteral("bias.cull_front=false"), QStringLiteral("bias.polygon_factor=2"),
                                                                 QStringLiteral("bias.polygon_units=4"), QStringLiteral("bias.slope=0"),
                                                                 QStringLiteral("bias.min=0")})});
    // The defaults' bias, one part of it off at a time, and the receiver plane in its place.
    s.push_back({QStringLiteral("no front-face culling"), {QStringLiteral("bias.cull_front=false")}});
    s.push_back({QStringLiteral("no footprint bias"), {QStringLiteral("bias.footprint=false")}});
    s.push_back({QStringLiteral("floors in the map"), {QStringLiteral("bias.skip_floors=false")}});
    s.push_back({QStringLiteral("receiver-plane taps"), {QStringLiteral("bias.receiver_plane=true")}});
    return s;
}

} // namespace

// The tutorial most learners copy: 3 x 3 PCF on a 1024 map, bias 0.05/0.005 in depth units,
// front faces, the hand-set volume; one plain map drawn every frame, whatever rig the base has
// (cascades, a virtual map, a warp and a cache need a fitted light or are not the tutorial's).
QStringList tutorialAssignments()
{
    return {QStringLiteral("shadow.enabled=true"), QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=3"),
            QStringLiteral("map.size=1024"), QStringLiteral("map.format=depth24"),
            QStringLiteral("bias.space=depth"), QStringLiteral("bias.slope=0.05"), QStringLiteral("bias.min=0.005"),
            QStringLiteral("bias.cull_front=false"), QStringLiteral("light.fit=manual"),
            QStringLiteral("filter.early_out=false"), QStringLiteral("shadow.cascades=1"), QStringLiteral("shadow.virtual=false"),
            QStringLiteral("light.warp=none"), QStringLiteral("shadow.cache=off")};
}

namespace {

// A light placed `offset` (x,y,z in the seed's units; null: the scene's own light) from the
// scene's target: on a preset as written, around the origin; on a model scaled to its size
// (sceneScale()) around its own target, so "(-2, 4, -1)" sits above a 250-unit spider as above
// the seed, not inside it.
QStringList placedLight(const Settings& base, const char* offset)
{
    if (!offset)
        return {};
    const QStringList parts = QString::fromLatin1(offset).split(QLatin1Char(','));
    const glm::dvec3 d(parts.value(0).toDouble(), parts.value(1).toDouble(), parts.value(2).toDouble());
    const bool preset = isPresetName(base.scene);
    const double scale = preset ? 1.0 : sceneScale(base.scene);
    const glm::dvec3 target = preset ? glm::dvec3(0.0) : base.light.target;
    const glm::dvec3 position = target + d * scale;
    return {QStringLiteral("light.position=%1,%2,%3").arg(position.x, 0, 'g', 10).arg(position.y, 0, 'g', 10).arg(position.z, 0, 'g', 10),
            QStringLiteral("light.target=%1,%2,%3").arg(target.x, 0, 'g', 10).arg(target.y, 0, 'g', 10).arg(target.z, 0, 'g', 10)};
}

// A placement's name, with the scale its offsets take on a model ("(3, 2, 4) × 54.2").
QString placementName(const Settings& base, const char* name)
{
    const double scale = isPresetName(base.scene) ? 1.0 : sceneScale(base.scene);
    return scale == 1.0 || qstrcmp(name, "preset") == 0 ? QString::fromLatin1(name)
                                                          : QStringLiteral("%1 × %2").arg(QLatin1String(name)).arg(scale, 0, 'g', 3);
}

// Light placements around the preset's target, from overhead to grazing and from near to very
// far, each with the defaults and with the tutorial configuration.
std::vector<SweepEntry> lightsSweep(const Settings& base)
{
    std::vector<SweepEntry> s;
    const struct {
        const char* name;
        const char* position;   // relative to the target
    } placements[] = {{"preset", nullptr},
                      {"(-2, 4, -1)", "-2,4,-1"},
                      {"(-4, 8, -2), twice as far", "-4,8,-2"},
                      {"(-200, 400, -100)", "-200,400,-100"},
                      {"(1000, 1000, 1000)", "1000,1000,1000"},
                      {"(0.5, 8, 0.3), nearly overhead", "0.5,8,0.3"},
                      {"(0, 6, 0), straight above", "0,6,0"},
                      {"(3, 2, 4)", "3,2,4"},
                      {"(-6, 1.2, -2), grazing", "-6,1.2,-2"},
                      {"(5, 0.4, -3), 4 deg", "5,0.4,-3"}};
    for (const auto& p : placements) {
        const QStringList at = placedLight(base, p.position);
        s.push_back({QStringLiteral("defaults @ %1").arg(placementName(base, p.name)), at});
        s.push_back({QStringLiteral("tutorial @ %1").arg(placementName(base, p.name)), tutorialAssignments() + at});
    }
    return s;
}

// Penumbra-only filtering against every tap, for each technique that can skip its taps: the same
// image, so the difference is all cost.
std::vector<SweepEntry> penumbraSweep()
{
    std::vector<SweepEntry> s;
    for (const ShadowTechnique& technique : shadowTechniques()) {
        if (!technique.penumbraOnly)
            continue;
        for (const TechniqueVariation& variation : technique.sweep) {
            s.push_back({variation.label + QStringLiteral(", every tap"), variation.assignments + QStringList{QStringLiteral("filter.early_out=false")}});
            s.push_back({variation.label + QStringLiteral(", penumbra only"), variation.assignments + QStringList{QStringLiteral("filter.early_out=true")}});
        }
    }
    return s;
}

// 1-4 cascades at (about) equal total texels, each stabilised and not, and the split schemes:
// what cascades buy at the same memory, and what stabilisation does to flicker; then the
// filterable techniques on four cascades, which a single moments map cannot give a city.
std::vector<SweepEntry> cascadesSweep()
{
    std::vector<SweepEntry> s;
    const int sizes[] = {2048, 1448, 1182, 1024};   // 2048² / count, per cascade
    for (int count = 1; count <= 4; ++count) {
        for (bool stabilize : {true, false}) {
            s.push_back({QStringLiteral("%1 cascade%2 of %3 x %3, %4").arg(count).arg(count > 1 ? "s" : "").arg(sizes[count - 1])
                             .arg(stabilize ? QStringLiteral("stabilised") : QStringLiteral("unstabilised")),
                         {QStringLiteral("shadow.cascades=%1").arg(count), QStringLiteral("map.size=%1").arg(sizes[count - 1]),
                          QStringLiteral("light.stabilize=%1").arg(stabilize ? "true" : "false")}});
        }
    }
    for (const char* split : {"uniform", "logarithmic"})
        s.push_back({QStringLiteral("4 cascades of 1024 x 1024, %1 split").arg(QLatin1String(split)),
                     {QStringLiteral("shadow.cascades=4"), QStringLiteral("map.size=1024"), QStringLiteral("shadow.split=%1").arg(QLatin1String(split))}});
    // Sample-distribution cascades at the same texels: split over the depths the frame draws.
    for (bool stabilize : {true, false})
        s.push_back({QStringLiteral("4 cascades of 1024 x 1024, sdsm, %1").arg(stabilize ? QStringLiteral("stabilised") : QStringLiteral("unstabilised")),
                     {QStringLiteral("shadow.cascades=4"), QStringLiteral("map.size=1024"), QStringLiteral("shadow.depth_fit=sdsm"),
                      QStringLiteral("light.stabilize=%1").arg(stabilize ? "true" : "false")}});
    for (const char* technique : {"vsm", "evsm4", "msm"})
        s.push_back({QStringLiteral("4 cascades of 1024 x 1024, %1").arg(QLatin1String(technique)),
                     {QStringLiteral("shadow.cascades=4"), QStringLiteral("map.size=1024"), QStringLiteral("filter.mode=%1").arg(QLatin1String(technique))}});
    return s;
}

// LiSPSM against no warp at the same texels: at the preset's light, straight above (where the
// camera looking down sees along it) and grazing; its strength; and with cascades.
std::vector<SweepEntry> warpSweep(const Settings& base)
{
    std::vector<SweepEntry> s;
    const struct {
        const char* name;
        const char* position;   // relative to the target
    } placements[] = {{"preset", nullptr}, {"(0, 6, 0), straight above", "0,6,0"}, {"(-6, 1.2, -2), grazing", "-6,1.2,-2"}};
    for (const auto& p : placements) {
        const QStringList at = placedLight(base, p.position);
        s.push_back({QStringLiteral("no warp @ %1").arg(placementName(base, p.name)), at + QStringList{QStringLiteral("light.warp=none")}});
        s.push_back({QStringLiteral("lispsm @ %1").arg(placementName(base, p.name)), at + QStringList{QStringLiteral("light.warp=lispsm")}});
    }
    for (const char* scale : {"0.3", "3"})
        s.push_back({QStringLiteral("lispsm, warp scale %1").arg(QLatin1String(scale)),
                     {QStringLiteral("light.warp=lispsm"), QStringLiteral("light.warp_scale=%1").arg(QLatin1String(scale))}});
    for (const char* warp : {"none", "lispsm"})
        s.push_back({QStringLiteral("4 cascades of 1024 x 1024, warp %1").arg(QLatin1String(warp)),
                     {QStringLiteral("shadow.cascades=4"), QStringLiteral("map.size=1024"), QStringLiteral("light.warp=%1").arg(QLatin1String(warp))}});
    return s;
}

std::vector<SweepEntry> defaultSweep()
{
    std::vector<SweepEntry> s{{QStringLiteral("defaults"), {}},
                              {QStringLiteral("tutorial (pcf 3, 1024, 0.05/0.005 depth)"), tutorialAssignments()},
                              {QStringLiteral("perspective light"), {QStringLiteral("light.projection=perspective")}},
                              {QStringLiteral("depth32f"), {QStringLiteral("map.format=depth32f")}}};
    for (auto part : {filterSweep(), resolutionSweep(), biasSweep()})
        s.insert(s.end(), part.begin(), part.end());
    return s;
}

} // namespace

std::vector<SweepEntry> sweepAround(const Settings& base)
{
    const auto number = [](double v) { return QString::number(v, 'g', 17); };
    std::vector<SweepEntry> entries{{QStringLiteral("current settings"), {}}};
    for (const ShadowTechnique& technique : shadowTechniques()) {
        Settings s = base;
        s.filter.mode = technique.mode;
        entries.push_back({filterLabel(s.filter), {QStringLiteral("filter.mode=") + technique.key}});
        for (const TechniqueVariation& variation : technique.sweep) {
            Settings v = base;
            for (const QString& assignment : variation.assignments)
                applyAssignment(v, assignment);
            entries.push_back({filterLabel(v.filter), variation.assignments});
        }
    }
    for (const int size : {base.map.size / 2, base.map.size * 2})
        entries.push_back({QStringLiteral("map %1").arg(size) + QChar(0x00B2), {QStringLiteral("map.size=%1").arg(size)}});
    for (const double factor : {0.5, 2.0})
        entries.push_back({QStringLiteral("bias ×%1").arg(factor),
                           {QStringLiteral("bias.slope=") + number(base.bias.slope * factor), QStringLiteral("bias.min=") + number(base.bias.min * factor)}});
    // No bias at all: nor the footprint's, nor floors left out.
    entries.push_back({QStringLiteral("no bias"), {QStringLiteral("bias.slope=0"), QStringLiteral("bias.min=0"), QStringLiteral("bias.footprint=false"),
                                                   QStringLiteral("bias.skip_floors=false")}});
    entries.push_back({base.bias.footprint ? QStringLiteral("no footprint bias") : QStringLiteral("footprint bias"),
                       {QStringLiteral("bias.footprint=%1").arg(base.bias.footprint ? "false" : "true")}});
    entries.push_back({base.bias.cullFront ? QStringLiteral("no front-face culling") : QStringLiteral("front-face culling"),
                       {QStringLiteral("bias.cull_front=%1").arg(base.bias.cullFront ? "false" : "true")}});
    entries.push_back({base.contact.enabled ? QStringLiteral("no contact shadows") : QStringLiteral("contact shadows"),
                       {QStringLiteral("contact.enabled=%1").arg(base.contact.enabled ? "false" : "true")}});
    // Cascades split over the distance or over what the frame draws.
    if (base.shadow.cascades > 1 && base.light.type == LightType::Directional)
        entries.push_back({base.shadow.depthFit == DepthFit::Sdsm ? QStringLiteral("cascades over the distance") : QStringLiteral("sdsm cascades"),
                           {QStringLiteral("shadow.depth_fit=%1").arg(base.shadow.depthFit == DepthFit::Sdsm ? "distance" : "sdsm")}});
    // A directional light's map warped, or not.
    if (base.light.type == LightType::Directional)
        entries.push_back({base.light.warp == LightWarp::Lispsm ? QStringLiteral("no warp") : QStringLiteral("lispsm warp"),
                           {QStringLiteral("light.warp=%1").arg(base.light.warp == LightWarp::Lispsm ? "none" : "lispsm")}});
    // What ignoring a cut-out mask costs, where the scene has one.
    if (sceneHasCutouts(base.scene))
        entries.push_back({base.shadow.cutouts ? QStringLiteral("cut-outs cast whole") : QStringLiteral("cut-outs through their mask"),
                           {QStringLiteral("shadow.cutouts=%1").arg(base.shadow.cutouts ? "false" : "true")}});

    // Only what is valid on `base` (errors; warnings pass), each configuration once, the first
    // label kept.
    std::vector<SweepEntry> kept;
    std::vector<Settings> seen;
    for (const SweepEntry& entry : entries) {
        Settings s = base;
        try {
            for (const QString& a : entry.assignments)
                applyAssignment(s, a);
        } catch (const SettingsError&) {
            continue;   // out of a key's range (a map twice the largest)
        }
        const std::vector<SettingsIssue> issues = validate(s);  // errors come first
        if (!issues.empty() && issues.front().severity == SettingsIssue::Severity::Error)
            continue;
        if (std::find(seen.begin(), seen.end(), s) != seen.end())
            continue;
        seen.push_back(s);
        kept.push_back(entry);
    }
    return kept;
}

std::vector<SweepEntry> parseSweepFile(const QByteArray& bytes, const QString& path)
{
    const QString name = displayText(path);
    auto problem = [&](const QString& what) {
        return SettingsError(QString(), QStringLiteral("--sweep: '%1' %2; write [{\"label\": \"...\", \"set\": {\"key\": value}}, ...]").arg(name, what));
    };
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        throw SettingsError(QString(), QStringLiteral("--sweep: '%1' is not valid JSON at offset %2: %3").arg(name).arg(error.offset).arg(error.errorString()));
    if (doc.isObject() && !doc.object().value(QStringLiteral("configurations")).isArray())
        throw problem(QStringLiteral("is an object without a \"configurations\" array"));
    const QJsonArray array = doc.isArray() ? doc.array() : doc.object().value(QStringLiteral("configurations")).toArray();
    if (array.isEmpty())
        throw problem(QStringLiteral("holds no configurations"));
    std::vector<SweepEntry> sweep;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString where = QStringLiteral("entry %1").arg(i + 1);
        if (!array[i].isObject())
            throw problem(QStringLiteral("has %1 that is not an object").arg(where));
        const QJsonObject o = array[i].toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (it.key() != u"label" && it.key() != u"set")
                throw problem(QStringLiteral("has %1 with the unknown member '%2' (only \"label\" and \"set\")").arg(where, displayText(it.key())));
        }
        if (o.contains(QStringLiteral("label")) && !o.value(QStringLiteral("label")).isString())
            throw problem(QStringLiteral("has %1 whose \"label\" is not a string").arg(where));
        if (o.contains(QStringLiteral("set")) && !o.value(QStringLiteral("set")).isObject())
            throw problem(QStringLiteral("has %1 whose \"set\" is not an object of key: value").arg(where));
        SweepEntry entry{o.value(QStringLiteral("label")).toString(), {}};
        try {
            entry.assignments = assignmentsFromJson(o.value(QStringLiteral("set")).toObject());
        } catch (const SettingsError& e) {
            throw e.within(QStringLiteral("--sweep: in '%1', %2").arg(name, where));
        }
        if (entry.label.isEmpty())
            entry.label = entry.assignments.isEmpty() ? QStringLiteral("base") : entry.assignments.join(QStringLiteral(", "));
        sweep.push_back(entry);
    }
    return sweep;
}

// Virtual shadow maps against one map and against stabilised cascades of about the same
// memory (a pool of 30² pages of 136² is 4080², 16.6 M texels; 4 x 2048² is 16.8 M), with a
// filter, one level finer than a texel per pixel in the same pool (two texels a pixel a side:
// an edge placed to a quarter of a pixel, not a half), and with a pool too small for the view.
std::vector<SweepEntry> virtualSweep()
{
    const QString cascades = QStringLiteral("shadow.cascades=4");
    return {
        {QStringLiteral("1 map of 4096 x 4096"), {QStringLiteral("map.size=4096")}},
        {QStringLiteral("4 stabilised cascades of 2048 x 2048"), {cascades, QStringLiteral("map.size=2048"), QStringLiteral("light.stabilize=true")}},
        {QStringLiteral("4 stabilised cascades of 2048 x 2048, pcf 3x3"),
         {cascades, QStringLiteral("map.size=2048"), QStringLiteral("light.stabilize=true"), QStringLiteral("filter.mode=pcf")}},
        {QStringLiteral("virtual at its defaults (40 x 40 pages, a level finer)"), {QStringLiteral("shadow.virtual=true")}},
        {QStringLiteral("virtual at its defaults, pcf 3x3"), {QStringLiteral("shadow.virtual=true"), QStringLiteral("filter.mode=pcf")}},
        {QStringLiteral("virtual, 30 x 30 pages (the cascades' memory)"),
         {QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.virtual_pool=30")}},
        {QStringLiteral("virtual, 30 x 30 pages, no level finer"),
         {QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.virtual_pool=30"), QStringLiteral("shadow.virtual_lod_bias=0")}},
        {QStringLiteral("virtual, 6 x 6 pages"), {QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.virtual_pool=6")}},
    };
}

// shadow.cache's policies over a moving scene (report --animation): the exact ones (static,
// and pages on a virtual map) against off, the stale ones at their stalest, and each exact
// one under a moving sun (shadow.force_invalidate), its worst case.
std::vector<SweepEntry> cacheSweep(const Settings& base)
{
    const auto set = [](const char* value) { return QStringLiteral("shadow.cache=%1").arg(QLatin1String(value)); };
    const QString sun = QStringLiteral("shadow.force_invalidate=true");
    if (base.shadow.virtualMap)
        return {{QStringLiteral("off: every page drawn again when a caster moves"), {set("off")}},
                {QStringLiteral("pages: the pages a moved caster touches"), {set("pages")}},
                {QStringLiteral("pages, moving sun"), {set("pages"), sun}}};
    return {{QStringLiteral("off: every caster of every view"), {set("off")}},
            {QStringLiteral("static: moving casters over a copy of the still ones"), {set("static")}},
            {QStringLiteral("every-n, every 4th frame (at its stalest)"), {set("every-n"), QStringLiteral("shadow.cache_interval=4")}},
            {QStringLiteral("every-n, every 16th frame (at its stalest)"), {set("every-n"), QStringLiteral("shadow.cache_interval=16")}},
            {QStringLiteral("on-demand (drawn at the first instant)"), {set("on-demand")}},
            {QStringLiteral("static, moving sun"), {set("static"), sun}}};
}

QStringList builtInSweeps()
{
    return {QStringLiteral("default"), QStringLiteral("filters"), QStringLiteral("resolution"), QStringLiteral("bias"), QStringLiteral("lights"),
            QStringLiteral("penumbra"), QStringLiteral("cascades"), QStringLiteral("filterable"), QStringLiteral("warp"), QStringLiteral("virtual"),
            QStringLiteral("cache"), QStringLiteral("around")};
}

std::vector<SweepEntry> loadSweep(const QString& nameOrFile, const Settings& base)
{
    if (nameOrFile == u"around")
        return sweepAround(base);
    if (nameOrFile == u"default")
        return defaultSweep();
    if (nameOrFile == u"filters")
        return filterSweep();
    if (nameOrFile == u"resolution")
        return resolutionSweep();
    if (nameOrFile == u"bias")
        return biasSweep();
    if (nameOrFile == u"lights")
        return lightsSweep(base);
    if (nameOrFile == u"penumbra")
        return penumbraSweep();
    if (nameOrFile == u"cascades")
        return cascadesSweep();
    if (nameOrFile == u"warp")
        return warpSweep(base);
    if (nameOrFile == u"virtual")
        return virtualSweep();
    if (nameOrFile == u"cache")
        return cacheSweep(base);
    if (nameOrFile == u"filterable")
        return filterableSweep();
    QByteArray bytes;
    try {
        bytes = readInputFile(nameOrFile, QStringLiteral("sweep file"));
    } catch (const SettingsError& e) {
        throw SettingsError(QString(), QStringLiteral("--sweep: %1%2; give a file or one of %3")
                                           .arg(QString::fromStdString(e.what()), didYouMean(nameOrFile, builtInSweeps()),
                                                builtInSweeps().join(QStringLiteral(", "))));
    }
    return parseSweepFile(bytes, nameOrFile);
}

Settings applySweepEntry(const Settings& base, const SweepEntry& entry)
{
    Settings s = base;
    try {
        for (const QString& a : entry.assignments)
            applyAssignment(s, a);
        ensureValid(s);
    } catch (const SettingsError& e) {
        throw e.within(QStringLiteral("in sweep entry '%1'").arg(displayText(entry.label)));
    }
    return s;
}

std::vector<SweepConfiguration> distinctConfigurations(const Settings& base, const std::vector<SweepEntry>& sweep)
{
    std::vector<SweepConfiguration> configurations;
    for (const SweepEntry& entry : sweep) {
        const Settings settings = applySweepEntry(base, entry);
        const auto same = std::find_if(configurations.begin(), configurations.end(), [&](const SweepConfiguration& c) { return c.settings == settings; });
        if (same == configurations.end())
            configurations.push_back({entry.label, entry.assignments, settings});
        else if (!same->label.split(QStringLiteral(" = ")).contains(entry.label))
            same->label += QStringLiteral(" = ") + entry.label;
    }
    return configurations;
}

} // namespace shadowlab
