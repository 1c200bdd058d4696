#include "SettingsKeys.h"

#include "Limits.h"
#include "SceneNames.h"
#include "InputFile.h"
#include "MessageText.h"
#include "OutputFile.h"
#include "SettingsError.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"
#include "VirtualPages.h"
#include "MomentMath.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <glm/geometric.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <functional>
#include <optional>
#include <tuple>

namespace shadowlab {

namespace {

constexpr double kMaxCoordinate = 1e7;

struct Range {
    double lo;
    double hi;
    bool loOpen = false;
    bool hiOpen = false;

    bool contains(double v) const
    {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    QString text() const
    {
        return QStringLiteral("%1%2, %3%4")
            .arg(loOpen ? QLatin1Char('(') : QLatin1Char('['))
            .arg(lo)
            .arg(hi)
            .arg(hiOpen ? QLatin1Char(')') : QLatin1Char(']'));
    }
};

QString formatNumber(double v)
{
    return QString::number(v, 'g', 15);
}

QString formatVec3(const glm::dvec3& v)
{
    return QStringLiteral("%1,%2,%3").arg(formatNumber(v.x), formatNumber(v.y), formatNumber(v.z));
}

std::optional<QString> checkNumber(double v, const Range& range)
{
    if (!std::isfinite(v))
        return QStringLiteral("must be a finite number in %1, not %2").arg(range.text(), formatNumber(v));
    if (!range.contains(v))
        return QStringLiteral("%1 is out of range; allowed: %2").arg(formatNumber(v), range.text());
    return std::nullopt;
}

std::optional<QString> checkVec3(const glm::dvec3& v)
{
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v[i]) || std::abs(v[i]) > kMaxCoordinate)
            return QStringLiteral("each coordinate must be finite with |x| <= %1, got %2")
                .arg(formatNumber(kMaxCoordinate), formatVec3(v));
    }
    return std::nullopt;
}

// Why `text`, which Qt would not read as a double, is refused: a number too small or too
// large for a double is called that, not "not a number".
QString numberProblem(const QString& text)
{
    const QByteArray latin = text.trimmed().toLatin1();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(latin.constData(), &end);
    if (!latin.isEmpty() && end == latin.constData() + latin.size() && errno == ERANGE) {
        if (std::abs(v) < 1.0)
            return QStringLiteral("'%1' is too small: it underflows to 0 in double precision (the smallest normal magnitude is %2); write 0 or a larger value")
                .arg(displayText(text))
                .arg(std::numeric_limits<double>::min());
        return QStringLiteral("'%1' is too large: it overflows double precision").arg(displayText(text));
    }
    return QStringLiteral("'%1' is not a number").arg(displayText(text));
}

double parseNumber(const QString& key, const QString& text, const Range& range)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok)
        throw SettingsError(key, QStringLiteral("%1; allowed: %2").arg(numberProblem(text), range.text()));
    if (auto problem = checkNumber(v, range))
        throw SettingsError(key, *problem);
    return v;
}

struct Entry {
    SettingKey info;
    std::function<QString(const Settings&)> get;
    std::function<void(Settings&, const QString&)> set;
    std::function<std::optional<QString>(const Settings&)> check;
};

// `v` as a whole number; a SettingsError naming `key` and what is `allowed` when it is not one.
int wholeNumber(const QString& key, const QString& v, const QString& allowed)
{
    bool ok = false;
    const int value = v.trimmed().toInt(&ok);
    if (!ok)
        throw SettingsError(key, QStringLiteral("'%1' is not a whole number; allowed: %2").arg(displayText(v), allowed));
    return value;
}

// Field accessors are generic lambdas `[](auto& s) -> auto& { return s.x.y; }` so that one
// accessor serves reading, writing and checking.
template <typename Field>
Entry numberKey(const char* key, Range range, Field field, const char* help)
{
    const QString k = QString::fromLatin1(key);
    return {SettingKey{k, QStringLiteral("number"), range.text(), QString::fromUtf8(help), {}, range.lo, range.hi, {}},
            [field](const Settings& s) { return formatNumber(field(s)); },
            [field, range, k](Settings& s, const QString& v) { field(s) = parseNumber(k, v, range); },
            [field, range](const Settings& s) { return checkNumber(field(s), range); }};
}

template <typename Field>
Entry integerKey(const char* key, int lo, int hi, bool oddOnly, Field field, const char* help)
{
    const QString k = QString::fromLatin1(key);
    const QString rangeText = QStringLiteral("[%1, %2]%3").arg(lo).arg(hi).arg(oddOnly ? QStringLiteral(", odd") : QString());
    auto check = [lo, hi, oddOnly, rangeText](int v) -> std::optional<QString> {
        if (v < lo || v > hi || (oddOnly && v % 2 == 0))
            return QStringLiteral("%1 is out of range; allowed: %2").arg(v).arg(rangeText);
        return std::nullopt;
    };
    return {SettingKey{k, QStringLiteral("integer"), rangeText, QString::fromUtf8(help), {}, double(lo), double(hi), {}},
            [field](const Settings& s) { return QString::number(field(s)); },
            [field, check, k, rangeText](Settings& s, const QString& v) {
                const int value = wholeNumber(k, v, rangeText);
                if (auto problem = check(value))
                    throw SettingsError(k, *problem);
                field(s) = value;
            },
            [field, check](const Settings& s) { return check(field(s)); }};
}

template <typename Field>
Entry boolKey(const char* key, Field field, const char* help)
{
    const QString k = QString::fromLatin1(key);
    return {SettingKey{k, QStringLiteral("bool"), QStringLiteral("true | false"), QString::fromUtf8(help), {}, 0, 1, {}},
            [field](const Settings& s) { return field(s) ? QStringLiteral("true") : QStringLiteral("false"); },
            [field, k](Settings& s, const QString& v) {
                const QString t = v.trimmed().toLower();
                if (t == u"true" || t == u"1" || t == u"on" || t == u"yes")
                    field(s) = true;
                else if (t == u"false" || t == u"0" || t == u"off" || t == u"no")
                    field(s) = false;
                else
                    throw SettingsError(k, QStringLiteral("'%1' is not a boolean; allowed: true | false").arg(displayText(v)));
            },
            [](const Settings&) { return std::optional<QString>(); }};
}

template <typename Field>
Entry vec3Key(const char* key, Field field, const char* help)
{
    const QString k = QString::fromLatin1(key);
    return {SettingKey{k, QStringLiteral("vec3"), QStringLiteral("x,y,z, each finite with |x| <= 1e7"), QString::fromUtf8(help), {},
                       -kMaxCoordinate, kMaxCoordinate, {}},
            [field](const Settings& s) { return formatVec3(field(s)); },
            [field, k](Settings& s, const QString& v) {
                const QStringList parts = v.split(QLatin1Char(','));
                if (parts.size() != 3)
                    throw SettingsError(k, QStringLiteral("'%1' is not a vector; write three numbers x,y,z").arg(displayText(v)));
                glm::dvec3 result;
                for (int i = 0; i < 3; ++i) {
                    bool ok = false;
                    result[i] = parts[i].trimmed().toDouble(&ok);
                    if (!ok)
                        throw SettingsError(k, QStringLiteral("'%1' is not a vector of three numbers x,y,z: %2").arg(displayText(v), numberProblem(parts[i])));
                }
                if (auto problem = checkVec3(result))
                    throw SettingsError(k, *problem);
                field(s) = result;
            },
            [field](const Settings& s) { return checkVec3(field(s)); }};
}

// An enum spelled by a fixed list of names, in the enum's order. `then` runs after a value is
// set, for keys that keep another in step (light.type and light.projection).
template <typename Enum, typename Field>
Entry choiceKey(const char* key, QStringList names, Field field, const char* help, std::function<void(Settings&)> then = {})
{
    const QString k = QString::fromLatin1(key);
    const QString rangeText = names.join(QStringLiteral(" | "));
    return {SettingKey{k, QStringLiteral("choice"), rangeText, QString::fromUtf8(help), names, 0, double(names.size() - 1), {}},
            [field, names](const Settings& s) { return names.value(int(field(s))); },
            [field, names, k, rangeText, then](Settings& s, const QString& v) {
                const int index = names.indexOf(v.trimmed().toLower());
                if (index < 0)
                    throw SettingsError(k, QStringLiteral("'%1' is not allowed%2; choose one of %3").arg(displayText(v), didYouMean(v, names), rangeText));
                field(s) = Enum(index);
                if (then)
                    then(s);
            },
            [](const Settings&) { return std::optional<QString>(); }};
}

const QStringList kProjectionNames{QStringLiteral("ortho"), QStringLiteral("perspective")};
const QStringList kLightTypeNames{QStringLiteral("directional"), QStringLiteral("spot"), QStringLiteral("point")};
const QStringList kSplitNames{QStringLiteral("uniform"), QStringLiteral("logarithmic"), QStringLiteral("practical")};
const QStringList kDepthFitNames{QStringLiteral("distance"), QStringLiteral("sdsm")};
const QStringList kFitNames{QStringLiteral("manual"), QStringLiteral("scene")};
const QStringList kWarpNames{QStringLiteral("none"), QStringLiteral("lispsm")};
const QStringList kBiasSpaceNames{QStringLiteral("world"), QStringLiteral("texel"), QStringLiteral("depth")};
const QStringList kFormatNames{QStringLiteral("depth24"), QStringLiteral("depth32f")};
// The filter.mode names, help and parameter keys come from the technique table.
const QStringList kFilterNames = [] {
    QStringList names;
    for (const ShadowTechnique& t : shadowTechniques())
        names << t.key;
    return names;
}();
const QStringList kMomentFormatNames{QStringLiteral("16"), QStringLiteral("32")};
const QStringList kShadingNames{QStringLiteral("phong"), QStringLiteral("blinn-phong")};

Entry sceneKey()
{
    const QStringList names = sceneNames();
    const QString rangeText = names.join(QStringLiteral(" | ")) + QStringLiteral(" | city:N (N buildings, 1..%1) | a model or scene file").arg(kMaxCityBuildings);
    return {SettingKey{QStringLiteral("scene"), QStringLiteral("choice"), rangeText,
                       QStringLiteral("Built-in scene preset, or the path of a model (glTF, OBJ, PLY, STL, COLLADA, FBX) or scene "
                                      "file (.json); choosing one also resets light and camera to the scene's"),
                       names, 0, double(names.size() - 1), {}},
            [](const Settings& s) { return s.scene; },
            [names, rangeText](Settings& s, const QString& v) {
                const QString name = v.trimmed().toLower();
                if (isPresetName(name)) {
                    s.scene = name;
                    return;
                }
                if (cityBuildingCount(name) < 0)
                    throw SettingsError(QStringLiteral("scene"), QStringLiteral("'%1': a city's building count must be a whole number in [1, %2], e.g. city:8000")
                                                                     .arg(displayText(v)).arg(kMaxCityBuildings));
                const QFileInfo file(v.trimmed());
                if (!file.isFile())
                    throw SettingsError(QStringLiteral("scene"), QStringLiteral("'%1': no such file, and not a preset (%2)%3; check the path")
                                                                     .arg(displayText(v), names.join(QStringLiteral(" | ")), didYouMean(v, names)));
                s.scene = file.absoluteFilePath();
            },
            [names](const Settings& s) -> std::optional<QString> {
                if (!isPresetName(s.scene) && !QFileInfo(s.scene).isFile())
                    return QStringLiteral("'%1': no such file, and not a preset (%2); check the path").arg(displayText(s.scene), names.join(QStringLiteral(" | ")));
                return std::nullopt;
            }};
}

// light.type and light.projection keep each other consistent: a file that names only the
// projection (as older files do) gets the type it meant.
Entry lightTypeKey()
{
    return choiceKey<LightType>(
        "light.type", kLightTypeNames, [](auto& s) -> auto& { return s.light.type; },
        "directional: a direction (sun), ortho map or cascades; spot: a position with a cone (light.fov, light.falloff), unlit "
        "outside it; point: a position casting every way through six cube faces, rendered only where they see a receiver; sets "
        "light.projection",
        [](Settings& s) {
            s.light.projection = s.light.type == LightType::Directional ? LightProjection::Ortho : LightProjection::Perspective;
        });
}

Entry projectionKey()
{
    return choiceKey<LightProjection>(
        "light.projection", kProjectionNames, [](auto& s) -> auto& { return s.light.projection; },
        "Ortho for a directional light (sun), perspective for a spot or point light; follows light.type (setting it chooses "
        "directional or, from a directional light, spot)",
        [](Settings& s) {
            if (s.light.projection == LightProjection::Ortho)
                s.light.type = LightType::Directional;
            else if (s.light.type == LightType::Directional)
                s.light.type = LightType::Spot;
        });
}

Entry filterModeKey()
{
    QStringList parts;
    for (const ShadowTechnique& t : shadowTechniques())
        parts << t.help;
    const QByteArray help = QStringLiteral("Shadow filter: %1").arg(parts.join(QStringLiteral("; "))).toUtf8();
    return choiceKey<FilterMode>("filter.mode", kFilterNames, [](auto& s) -> auto& { return s.filter.mode; }, help.constData());
}

// The dock's groups (settingGroups() lists them in order).
constexpr QLatin1String kLight("Light"), kShadowMap("Shadow map"), kBias("Bias"), kFiltering("Filtering"), kMomentsMap("Moments map"),
    kContact("Contact shadows"), kShading("Shading"), kReference("Reference"), kCamera("Camera"), kScene("Scene");

// `entry` with how the dock shows it.
Entry presented(Entry entry, SettingPresentation look)
{
    entry.info.presentation = std::move(look);
    return entry;
}

// A technique's parameter, typed and ranged as the technique table says.
Entry parameterKey(const TechniqueParameter& p)
{
    const QByteArray key = p.key.toLatin1();    // copied into the entry
    const QByteArray help = p.help.toUtf8();
    // Shown as the technique table says, its whole range on the slider.
    const auto look = [&p](int decimals) {
        return SettingPresentation{.label = p.label, .unit = p.unit, .decimals = decimals, .sliderLow = p.minimum, .sliderHigh = p.maximum,
                                   .group = kFiltering};
    };
    if (const auto* field = std::get_if<int FilterSettings::*>(&p.field))
        return presented(integerKey(key.constData(), int(p.minimum), int(p.maximum), p.oddOnly,
                                    [m = *field](auto& s) -> auto& { return s.filter.*m; }, help.constData()),
                         look(0));
    const auto member = std::get<double FilterSettings::*>(p.field);
    return presented(numberKey(key.constData(), Range{p.minimum, p.maximum}, [member](auto& s) -> auto& { return s.filter.*member; },
                               help.constData()),
                     look(p.decimals));
}

// The blur width: 0 for none or an odd tap count, so the kernel centres on the texel.
Entry blurKey()
{
    const QString k = QStringLiteral("moments.blur");
    const QString rangeText = QStringLiteral("0 | odd in [1, %1]").arg(kMaxMomentBlur);
    auto check = [rangeText](int v) -> std::optional<QString> {
        if (v < 0 || v > kMaxMomentBlur || (v != 0 && v % 2 == 0))
            return QStringLiteral("%1 is not allowed; use 0 (no blur) or an odd width in [1, %2], e.g. 3 or 7").arg(v).arg(kMaxMomentBlur);
        return std::nullopt;
    };
    return {SettingKey{k, QStringLiteral("integer"), rangeText,
                       QStringLiteral("Separable Gaussian blur of the moments map, its width in texels (moment techniques): wider "
                                      "softens the penumbra and hides aliasing for two full-map passes of that many taps, and "
                                      "spreads light bleeding further; 0 leaves the map as rendered"),
                       {}, 0.0, double(kMaxMomentBlur), {}},
            [](const Settings& s) { return QString::number(s.moments.blur); },
            [check, k, rangeText](Settings& s, const QString& v) {
                const int value = wholeNumber(k, v, rangeText);
                if (auto problem = check(value))
                    throw SettingsError(k, *problem);
                s.moments.blur = value;
            },
            [check](const Settings& s) { return check(s.moments.blur); }};
}

std::vector<Entry> makeEntries()
{
    std::vector<Entry> e;
    e.push_back(presented(sceneKey(),
                          {.label = QStringLiteral("Preset"), .group = kScene}));
    e.push_back(presented(vec3Key("light.position", [](auto& s) -> auto& { return s.light.position; },
                        "Where the light is; with an ortho light only its direction to the target matters"),
                          {.label = QStringLiteral("Position"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -10.0, .sliderHigh = 10.0, .group = kLight}));
    e.push_back(presented(vec3Key("light.target", [](auto& s) -> auto& { return s.light.target; },
                        "The point the light looks at; the centre of the shadow map"),
                          {.label = QStringLiteral("Target"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -5.0, .sliderHigh = 5.0, .group = kLight}));
    e.push_back(presented(lightTypeKey(),
                          {.label = QStringLiteral("Type"), .group = kLight}));
    e.push_back(presented(projectionKey(),
                          {.label = QStringLiteral("Projection"), .group = kLight}));
    e.push_back(presented(numberKey("light.falloff", Range{0.0, 1.0}, [](auto& s) -> auto& { return s.light.falloff; },
                          "Spot light: share of the cone's half-angle (light.fov) over which the light fades to nothing at the rim; 0 is a hard edge"),
                          {.label = QStringLiteral("Cone falloff"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 1.0, .group = kLight}));
    e.push_back(presented(numberKey("light.extent", Range{0.0, 1e6, true, false}, [](auto& s) -> auto& { return s.light.extent; },
                          "Ortho half-size in world units: larger covers more of the scene with coarser texels (blockier, more acne)"),
                          {.label = QStringLiteral("Extent"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = 0.5, .sliderHigh = 30.0, .group = kLight}));
    e.push_back(presented(numberKey("light.fov", Range{0.0, 180.0, true, true}, [](auto& s) -> auto& { return s.light.fov; },
                          "Perspective light's full angle in degrees: wider covers more with coarser texels"),
                          {.label = QStringLiteral("Field of view"), .unit = QStringLiteral("°"), .decimals = 1, .sliderLow = 10.0, .sliderHigh = 170.0, .group = kLight}));
    e.push_back(presented(numberKey("light.near", Range{-1e7, 1e7}, [](auto& s) -> auto& { return s.light.nearPlane; },
                          "Light near plane in world units (> 0 for perspective): pushing it out buys depth precision, casters before it are clamped"),
                          {.label = QStringLiteral("Near"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -10.0, .sliderHigh = 20.0, .group = kLight}));
    e.push_back(presented(numberKey("light.far", Range{-1e7, 1e7}, [](auto& s) -> auto& { return s.light.farPlane; },
                          "Light far plane in world units: beyond it everything is lit; a tight far plane buys depth precision"),
                          {.label = QStringLiteral("Far"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = 0.5, .sliderHigh = 60.0, .group = kLight}));
    e.push_back(presented(numberKey("light.radius", Range{0.0, 100.0}, [](auto& s) -> auto& { return s.reference.lightRadius; },
                          "Radius of the disk light the area reference traces (world units): the soft shadow filtered modes are measured against"),
                          {.label = QStringLiteral("Light radius"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.0, .sliderHigh = 2.0, .group = kReference}));
    e.push_back(presented(choiceKey<LightFit>("light.fit", kFitNames, [](auto& s) -> auto& { return s.light.fit; },
                                    "scene: shrink the light volume (extent or fov, near, far) to what casts onto what the camera sees, for smaller texels and finer depth; manual: use it as set"),
                          {.label = QStringLiteral("Volume"), .group = kLight}));
    e.push_back(presented(boolKey("light.stabilize", [](auto& s) -> auto& { return s.light.stabilize; },
                        "Snap the fitted volume to whole texels and coarse size steps: no shimmer and no shadow-pass redraw on small camera moves, at slightly larger texels"),
                          {.label = QStringLiteral("Stabilise the fitted volume"), .group = kLight}));
    e.push_back(presented(choiceKey<LightWarp>("light.warp", kWarpNames, [](auto& s) -> auto& { return s.light.warp; },
                                     "Directional lights: none, or lispsm (light-space perspective shadow maps): the map warped by a perspective "
                                     "across it, so receivers near the camera get more texels and far ones fewer; no warp where the camera looks "
                                     "along the light, and a new map whenever the camera moves"),
                          {.label = QStringLiteral("Warp"), .group = kLight}));
    e.push_back(presented(numberKey("light.warp_scale", Range{0.05, 100.0}, [](auto& s) -> auto& { return s.light.warpScale; },
                          "With light.warp=lispsm: the warp's near distance as a multiple of Wimmer's optimum; below 1 a stronger warp "
                          "(finer near the camera, coarser far away), above 1 a weaker one"),
                          {.label = QStringLiteral("Warp scale"), .decimals = 2, .sliderLow = 0.1, .sliderHigh = 10.0, .logarithmic = true, .group = kLight}));
    e.push_back(presented(integerKey("map.size", 16, kMaxImageSide, false, [](auto& s) -> auto& { return s.map.size; },
                           "Shadow map texels per side: more texels, sharper edges and less acne, at more memory and shadow-pass time"),
                          {.label = QStringLiteral("Size"), .unit = QStringLiteral(" px"), .sliderLow = 64.0, .sliderHigh = 8192.0, .logarithmic = true, .group = kShadowMap}));
    e.push_back(presented(choiceKey<DepthFormat>("map.format", kFormatNames, [](auto& s) -> auto& { return s.map.format; },
                                       "Depth texture format: 32-bit float keeps precision with far-away near/far ratios"),
                          {.label = QStringLiteral("Depth format"), .group = kShadowMap}));
    e.push_back(presented(choiceKey<BiasSpace>("bias.space", kBiasSpaceNames, [](auto& s) -> auto& { return s.bias.space; },
                                     "Unit of bias.slope and bias.min: world units along the ray to the light (same offset for any near/far, map size or fit), texels of the map (follows the resolution), or depth-buffer units (the classic form, whose world offset grows with far - near)"),
                          {.label = QStringLiteral("Unit"), .group = kBias}));
    e.push_back(presented(numberKey("bias.slope", Range{0.0, 100.0}, [](auto& s) -> auto& { return s.bias.slope; },
                          "Slope-scaled bias, times (1 - N.L), in the unit of bias.space (world units, texels, or depth units <= 0.5): too little shows acne on lit slopes, too much detaches shadows (peter panning)"),
                          {.label = QStringLiteral("Slope"), .decimals = 4, .sliderLow = 0.0, .sliderHigh = 0.5, .group = kBias}));
    e.push_back(presented(numberKey("bias.min", Range{0.0, 100.0}, [](auto& s) -> auto& { return s.bias.min; },
                          "Minimum bias, in the unit of bias.space (world units, texels, or depth units <= 0.5): removes acne on surfaces facing the light, too much makes shadows leak at contacts"),
                          {.label = QStringLiteral("Minimum"), .decimals = 4, .sliderLow = 0.0, .sliderHigh = 0.1, .group = kBias}));
    e.push_back(presented(numberKey("bias.normal", Range{0.0, 8.0}, [](auto& s) -> auto& { return s.bias.normal; },
                          "Normal-offset bias in shadow-map texels: looks the shadow up from a point moved off the surface, against acne at grazing angles without detaching contact shadows as much as depth bias"),
                          {.label = QStringLiteral("Normal offset"), .unit = QStringLiteral(" texels"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 8.0, .group = kBias}));
    e.push_back(presented(boolKey("bias.cull_front", [](auto& s) -> auto& { return s.bias.cullFront; },
                        "Render back faces into the shadow map: removes acne on closed lit faces, can leak light where thin casters touch"),
                          {.label = QStringLiteral("Cull front faces in the shadow pass"), .group = kBias}));
    e.push_back(presented(numberKey("bias.polygon_factor", Range{-16.0, 16.0}, [](auto& s) -> auto& { return s.bias.polygonFactor; },
                          "glPolygonOffset factor in the shadow pass: hardware slope bias, against acne at the cost of peter panning"),
                          {.label = QStringLiteral("Offset factor"), .decimals = 2, .sliderLow = -4.0, .sliderHigh = 8.0, .group = kBias}));
    e.push_back(presented(numberKey("bias.polygon_units", Range{-10000.0, 10000.0}, [](auto& s) -> auto& { return s.bias.polygonUnits; },
                          "glPolygonOffset units in the shadow pass: constant hardware bias in depth-buffer steps"),
                          {.label = QStringLiteral("Offset units"), .sliderLow = -500.0, .sliderHigh = 5000.0, .group = kBias}));
    e.push_back(presented(boolKey("bias.receiver_plane", [](auto& s) -> auto& { return s.bias.receiverPlane; },
                        "Wide filters (pcf, poisson, pcss) compare each tap against the receiver's plane (its depth gradient in shadow-map space): no over-darkening of lit slopes by wide kernels with a small bias, but acne or leaks on curved receivers and at silhouettes, where the gradient is wrong"),
                          {.label = QStringLiteral("Receiver-plane depth for wide filters"), .group = kBias}));
    e.push_back(presented(filterModeKey(),
                          {.label = QStringLiteral("Filter"), .group = kFiltering}));
    for (const TechniqueParameter& parameter : techniqueParameters())
        e.push_back(parameterKey(parameter));
    e.push_back(presented(boolKey("filter.early_out", [](auto& s) -> auto& { return s.filter.earlyOut; },
                        "Penumbra-only filtering: pcf, poisson and pcss skip their taps where a min/max depth mip of the map shows the whole footprint lit or shadowed; the same image, less time outside penumbrae, a mip built with each shadow pass"),
                          {.label = QStringLiteral("Filter only penumbrae"), .group = kFiltering}));
    e.push_back(presented(choiceKey<MomentFormat>("moments.format", kMomentFormatNames, [](auto& s) -> auto& { return s.moments.format; },
                                        "Bits per channel of the moments map (moment techniques): 16 halves memory and bandwidth, but "
                                        "holds only small exponents (evsm <= 5.54, esm <= 11.08) and needs a larger filter.moment_bias; "
                                        "msm then stores Peters and Klein's optimised quantisation"),
                          {.label = QStringLiteral("Format"), .group = kMomentsMap}));
    e.push_back(presented(blurKey(),
                          {.label = QStringLiteral("Blur"), .unit = QStringLiteral(" texels"), .sliderLow = 0.0, .sliderHigh = 31.0, .group = kMomentsMap}));
    e.push_back(presented(boolKey("moments.mipmaps", [](auto& s) -> auto& { return s.moments.mipmaps; },
                        "Mipmaps of the moments map (moment techniques), built after each moments pass: trilinear lookups keep "
                        "distant and grazing shadows smooth instead of aliased, at the cost of a mip build and blurrier far shadows"),
                          {.label = QStringLiteral("Mipmaps"), .group = kMomentsMap}));
    e.push_back(presented(integerKey("moments.anisotropy", 1, 16, false, [](auto& s) -> auto& { return s.moments.anisotropy; },
                           "Anisotropic filtering of the moments map (moment techniques), 1 for off: sharper shadows on receivers seen "
                           "at grazing angles for more texture reads; capped at what the driver offers"),
                          {.label = QStringLiteral("Anisotropy"), .sliderLow = 1.0, .sliderHigh = 16.0, .group = kMomentsMap}));
    e.push_back(presented(integerKey("moments.view", 1, 4, false, [](auto& s) -> auto& { return s.moments.view; },
                           "Which stored moment the depth-map view shows for a moment technique: 1 is depth (unwarped for esm and "
                           "evsm, linear for a perspective light), 2 to 4 the higher ones as stored (exponential ones on a log scale)"),
                          {.label = QStringLiteral("Moment shown"), .sliderLow = 1.0, .sliderHigh = 4.0, .group = kMomentsMap}));
    e.push_back(presented(boolKey("shadow.enabled", [](auto& s) -> auto& { return s.shadow.enabled; },
                        "Shadows on or off: off skips the shadow pass entirely"),
                          {.label = QStringLiteral("Shadows"), .group = kShading}));
    e.push_back(presented(integerKey("shadow.cascades", 1, kMaxCascades, false, [](auto& s) -> auto& { return s.shadow.cascades; },
                           "Cascaded shadow maps for a directional light: the view up to shadow.distance split into this many slices, each with a map.size map of its own (more texels near the camera); 1 fits one map to the whole view"),
                          {.label = QStringLiteral("Cascades"), .sliderLow = 1.0, .sliderHigh = 4.0, .group = kShadowMap}));
    e.push_back(presented(choiceKey<CascadeSplit>("shadow.split", kSplitNames, [](auto& s) -> auto& { return s.shadow.split; },
                                        "Where cascades split: uniform (equal depth slices, coarse near the camera), logarithmic (equal ratios, tiny first slices) or practical (a blend by shadow.split_lambda)"),
                          {.label = QStringLiteral("Cascade split"), .group = kShadowMap}));
    e.push_back(presented(choiceKey<DepthFit>("shadow.depth_fit", kDepthFitNames, [](auto& s) -> auto& { return s.shadow.depthFit; },
                                        "With cascades: the depth range they split, distance (the camera's near plane to shadow.distance) or "
                                        "sdsm (sample-distribution shadow maps: from the nearest to the farthest pixel drawn, up to "
                                        "shadow.distance, read from a depth prepass of the frame; more texels where the view has receivers)"),
                          {.label = QStringLiteral("Cascade depth range"), .group = kShadowMap}));
    e.push_back(presented(numberKey("shadow.split_lambda", Range{0.0, 1.0}, [](auto& s) -> auto& { return s.shadow.splitLambda; },
                          "Practical split: 0 uniform, 1 logarithmic"),
                          {.label = QStringLiteral("Split λ"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 1.0, .group = kShadowMap}));
    e.push_back(presented(numberKey("shadow.distance", Range{0.0, 1e7, true, false}, [](auto& s) -> auto& { return s.shadow.distance; },
                          "With cascades: world units from the camera up to which receivers get shadows; beyond it they are lit"),
                          {.label = QStringLiteral("Shadow distance"), .unit = QStringLiteral(" wu"), .decimals = 1, .sliderLow = 1.0, .sliderHigh = 2000.0, .logarithmic = true, .group = kShadowMap}));
    e.push_back(presented(numberKey("shadow.blend", Range{0.0, 0.5}, [](auto& s) -> auto& { return s.shadow.blend; },
                          "With cascades: share of each cascade's depth, at its far end, over which it fades into the next (hides the seam's change of resolution)"),
                          {.label = QStringLiteral("Cascade blend"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 0.5, .group = kShadowMap}));
    e.push_back(presented(boolKey("shadow.show_cascades", [](auto& s) -> auto& { return s.shadow.showCascades; },
                        "Tint receivers by the cascade (red, green, blue, yellow) or cube face they read: where each map's texels go"),
                          {.label = QStringLiteral("Tint by cascade or cube face"), .group = kShadowMap}));
    e.push_back(presented(boolKey("shadow.cutouts", [](auto& s) -> auto& { return s.shadow.cutouts; },
                        "Cut-out casters (glTF alphaMode MASK: leaves, fences) cast through their holes, a texture lookup and discard "
                        "in the shadow pass; off casts them as solid as their quads, as a renderer that ignores the mask "
                        "(the eye and the reference still see the holes, so the report shows what ignoring it costs)"),
                          {.label = QStringLiteral("Cut-out casters"), .group = kShadowMap}));
    e.push_back(presented(boolKey("shadow.virtual", [](auto& s) -> auto& { return s.shadow.virtualMap; },
                        "Virtual shadow maps (directional lights): clipmap levels of 16384² texels cut into 128² pages; each visible "
                        "pixel asks for the page of the level whose texel covers at most one screen pixel, and only those pages are "
                        "drawn, into a pool of shadow.virtual_pool² pages, and kept until the light or the scene changes; "
                        "replaces map.size and cascades"),
                          {.label = QStringLiteral("Virtual shadow map"), .group = kShadowMap}));
    e.push_back(presented(integerKey("shadow.virtual_pool", 4, 64, false, [](auto& s) -> auto& { return s.shadow.virtualPool; },
                           "With shadow.virtual: pages per side of the physical pool (each 128² texels and a 4-texel border), the "
                           "memory budget; when a view asks for more pages, the finest ones are coarsened a level, with a warning"),
                          {.label = QStringLiteral("Page pool (per side)"), .unit = QStringLiteral(" pages"), .sliderLow = 4.0, .sliderHigh = 64.0, .group = kShadowMap}));
    e.push_back(presented(integerKey("shadow.virtual_levels", 1, 16, false, [](auto& s) -> auto& { return s.shadow.virtualLevels; },
                           "With shadow.virtual: clipmap levels; the coarsest holds the whole scene in 2 x 2 pages (256 texels "
                           "across), each finer one has half its texel, so the finest texel is the scene's width / 256 / 2^(levels - 1)"),
                          {.label = QStringLiteral("Clipmap levels"), .sliderLow = 1.0, .sliderHigh = 16.0, .group = kShadowMap}));
    e.push_back(presented(integerKey("shadow.virtual_lod_bias", 0, 4, false, [](auto& s) -> auto& { return s.shadow.virtualLodBias; },
                           "With shadow.virtual: how many levels finer than one texel per screen pixel each pixel asks for; every "
                           "level halves the texel, so a shadow edge's error shrinks to half a pixel and less, for about four "
                           "times the pages a level"),
                          {.label = QStringLiteral("Level bias (finer)"), .sliderLow = 0.0, .sliderHigh = 4.0, .group = kShadowMap}));
    e.push_back(presented(boolKey("contact.enabled", [](auto& s) -> auto& { return s.contact.enabled; },
                        "Contact shadows: a short march toward the light over the camera's depth of the casters (front and back faces), "
                        "combined with the map's shadow as the smaller visibility; brings back the shadow a bias lifts off contacts "
                        "(peter panning), for two depth prepasses and 2 x contact.steps lookups a pixel; finds only casters on screen"),
                          {.label = QStringLiteral("Contact shadows"), .group = kContact}));
    e.push_back(presented(numberKey("contact.length", Range{0.0, 1e6, true, false}, [](auto& s) -> auto& { return s.contact.length; },
                          "World units the contact march goes toward the light: longer finds casters farther from the receiver, with "
                          "coarser steps and more false shadow behind thin objects"),
                          {.label = QStringLiteral("Length"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.01, .sliderHigh = 10.0, .logarithmic = true, .group = kContact}));
    e.push_back(presented(integerKey("contact.steps", 1, 64, false, [](auto& s) -> auto& { return s.contact.steps; },
                           "Depth lookups of the contact march: more steps miss fewer thin casters, linearly more time"),
                          {.label = QStringLiteral("Steps"), .sliderLow = 1.0, .sliderHigh = 64.0, .group = kContact}));
    e.push_back(presented(numberKey("contact.thickness", Range{0.0, 1e6, true, false}, [](auto& s) -> auto& { return s.contact.thickness; },
                          "World units a caster may extend behind the front face the camera sees, at most; within it the march "
                          "is in shadow only between a caster's front and back faces, so light passing behind a caster stays lit. "
                          "It bounds casters with no back faces (open meshes): too thin misses the inside of thick ones"),
                          {.label = QStringLiteral("Thickness"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.001, .sliderHigh = 10.0, .logarithmic = true, .group = kContact}));
    e.push_back(presented(choiceKey<ShadingModel>("shading.model", kShadingNames, [](auto& s) -> auto& { return s.shading.model; },
                                        "Specular model: Blinn-Phong (half vector) or Phong (reflection vector)"),
                          {.label = QStringLiteral("Specular"), .group = kShading}));
    e.push_back(presented(boolKey("shading.texel_density", [](auto& s) -> auto& { return s.shading.texelDensity; },
                        "Tint the scene by screen pixels per shadow-map texel: blue under 1 (the map is finer than the screen), green about 1 to 2, "
                        "yellow to red from 4 up (blocky edges); shadows and measurements are unchanged"),
                          {.label = QStringLiteral("Texel density overlay"), .group = kShading}));
    e.push_back(presented(vec3Key("camera.position", [](auto& s) -> auto& { return s.camera.position; }, "Where the viewer is"),
                          {.label = QStringLiteral("Position"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -20.0, .sliderHigh = 20.0, .group = kCamera}));
    e.push_back(presented(vec3Key("camera.target", [](auto& s) -> auto& { return s.camera.target; }, "The point the viewer looks at"),
                          {.label = QStringLiteral("Target"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -5.0, .sliderHigh = 5.0, .group = kCamera}));
    e.push_back(presented(numberKey("camera.fov", Range{1.0, 170.0}, [](auto& s) -> auto& { return s.camera.fov; },
                          "Camera vertical field of view in degrees"),
                          {.label = QStringLiteral("Field of view"), .unit = QStringLiteral("°"), .decimals = 1, .sliderLow = 10.0, .sliderHigh = 120.0, .group = kCamera}));
    return e;
}

const std::vector<Entry>& entries()
{
    static const std::vector<Entry> table = makeEntries();
    return table;
}

const Entry& entryFor(const QString& key)
{
    for (const Entry& e : entries()) {
        if (e.info.key == key)
            return e;
    }
    QStringList keys;
    for (const Entry& e : entries())
        keys << e.info.key;
    throw SettingsError(key, QStringLiteral("unknown setting%1; run `shadowlab settings` for the list of keys").arg(didYouMean(key, keys)));
}

void flattenJson(const QJsonObject& object, const QString& prefix, std::vector<std::pair<QString, QJsonValue>>& out)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString key = prefix.isEmpty() ? it.key() : prefix + QLatin1Char('.') + it.key();
        if (it.value().isObject())
            flattenJson(it.value().toObject(), key, out);
        else
            out.emplace_back(key, it.value());
    }
}

QString jsonValueText(const QString& key, const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return formatNumber(value.toDouble());
    case QJsonValue::String:
        return value.toString();
    case QJsonValue::Array: {
        QStringList parts;
        for (const QJsonValue& v : value.toArray()) {
            if (!v.isDouble())
                throw SettingsError(key, QStringLiteral("arrays must hold numbers, e.g. [1, 2, 3]"));
            parts << formatNumber(v.toDouble());
        }
        return parts.join(QLatin1Char(','));
    }
    default:
        throw SettingsError(key, QStringLiteral("null or undefined is not a value; give a number, string, boolean or [x, y, z]"));
    }
}

} // namespace

const QStringList& settingGroups()
{
    static const QStringList groups{kLight, kShadowMap, kBias, kFiltering, kMomentsMap, kContact, kShading, kReference, kCamera, kScene};
    return groups;
}

const std::vector<SettingKey>& settingKeys()
{
    static const std::vector<SettingKey> keys = [] {
        std::vector<SettingKey> k;
        for (const Entry& e : entries())
            k.push_back(e.info);
        return k;
    }();
    return keys;
}

const SettingKey* findSettingKey(const QString& key)
{
    for (const SettingKey& k : settingKeys()) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}

QString settingValue(const Settings& settings, const QString& key)
{
    return entryFor(key).get(settings);
}

void applySetting(Settings& settings, const QString& key, const QString& value)
{
    entryFor(key.trimmed()).set(settings, value);
}

void applyAssignment(Settings& settings, const QString& assignment)
{
    const qsizetype eq = assignment.indexOf(QLatin1Char('='));
    if (eq <= 0)
        throw SettingsError(QString(), QStringLiteral("'%1' is not key=value, e.g. --set bias.slope=0.01").arg(displayText(assignment)));
    applySetting(settings, assignment.left(eq), assignment.mid(eq + 1));
}

QJsonObject settingsToJson(const Settings& settings)
{
    QJsonObject object;
    for (const Entry& e : entries()) {
        const QString text = e.get(settings);
        if (e.info.type == u"number" || e.info.type == u"integer")
            object.insert(e.info.key, text.toDouble());
        else if (e.info.type == u"bool")
            object.insert(e.info.key, text == u"true");
        else if (e.info.type == u"vec3") {
            QJsonArray array;
            for (const QString& part : text.split(QLatin1Char(',')))
                array.append(part.toDouble());
            object.insert(e.info.key, array);
        } else
            object.insert(e.info.key, text);
    }
    return object;
}

QStringList assignmentsFromJson(const QJsonObject& object)
{
    std::vector<std::pair<QString, QJsonValue>> flat;
    flattenJson(object, QString(), flat);
    QStringList assignments;
    for (const auto& [key, value] : flat)
        assignments << key + QLatin1Char('=') + jsonValueText(key, value);
    return assignments;
}

Settings settingsFromJson(const QJsonObject& object, const Settings& base)
{
    std::vector<std::pair<QString, QJsonValue>> flat;
    flattenJson(object, QString(), flat);
    Settings result = base;
    for (const auto& [key, value] : flat)
        applySetting(result, key, jsonValueText(key, value));
    return result;
}

QJsonObject readSettingsObject(const QString& path)
{
    const QByteArray bytes = readInputFile(path, QStringLiteral("settings file"));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        throw SettingsError(QString(), QStringLiteral("settings file '%1' is not valid JSON at offset %2: %3")
                                           .arg(displayText(path))
                                           .arg(error.offset)
                                           .arg(error.errorString()));
    if (!doc.isObject())
        throw SettingsError(QString(), QStringLiteral("settings file '%1' must hold a JSON object of key: value pairs").arg(displayText(path)));
    return doc.object();
}

Settings settingsFromFileObject(const QString& path, const QJsonObject& object, const Settings& base)
{
    try {
        return settingsFromJson(object, base);
    } catch (const SettingsError& e) {
        throw SettingsError(e.key(), QStringLiteral("in '%1': %2").arg(displayText(path), QString::fromStdString(e.what())));
    }
}

Settings loadSettingsFile(const QString& path, const Settings& base)
{
    return settingsFromFileObject(path, readSettingsObject(path), base);
}

void saveSettingsFile(const QString& path, const Settings& settings)
{
    checkOutputFile(path, QStringLiteral("settings file"));
    writeOutputFile(path, QJsonDocument(settingsToJson(settings)).toJson(QJsonDocument::Indented));
}

QString toString(LightProjection value) { return kProjectionNames.value(int(value)); }
QString toString(LightType value) { return kLightTypeNames.value(int(value)); }
QString toString(CascadeSplit value) { return kSplitNames.value(int(value)); }
QString toString(DepthFit value) { return kDepthFitNames.value(int(value)); }
QString toString(LightFit value) { return kFitNames.value(int(value)); }
QString toString(LightWarp value) { return kWarpNames.value(int(value)); }
QString toString(DepthFormat value) { return kFormatNames.value(int(value)); }
QString toString(BiasSpace value) { return kBiasSpaceNames.value(int(value)); }
QString toString(FilterMode value) { return kFilterNames.value(int(value)); }
QString toString(ShadingModel value) { return kShadingNames.value(int(value)); }
QString toString(MomentFormat value) { return kMomentFormatNames.value(int(value)); }

std::vector<SettingsIssue> validate(const Settings& s)
{
    std::vector<SettingsIssue> errors;
    std::vector<SettingsIssue> warnings;
    auto error = [&](const char* key, const QString& message) {
        errors.push_back({SettingsIssue::Severity::Error, QString::fromLatin1(key), message});
    };

    for (const Entry& e : entries()) {
        if (auto problem = e.check(s))
            errors.push_back({SettingsIssue::Severity::Error, e.info.key, *problem});
    }
    if (!errors.empty())
        return errors; // cross-field rules mean little while a field itself is broken

    const double lightDistance = glm::length(s.light.position - s.light.target);
    if (!(lightDistance > 1e-9 * std::max(1.0, glm::length(s.light.target))))
        error("light.position", QStringLiteral("the light is at its target; move light.position away from light.target"));
    if (glm::length(s.camera.position - s.camera.target) <= 1e-9 * std::max(1.0, glm::length(s.camera.target)))
        error("camera.position", QStringLiteral("the camera is at its target; move camera.position away from camera.target"));
    if (s.light.projection == LightProjection::Perspective && s.light.nearPlane <= 0.0)
        error("light.near", QStringLiteral("a perspective light needs near > 0 (got %1); try 0.1").arg(formatNumber(s.light.nearPlane)));
    if (s.light.nearPlane >= s.light.farPlane)
        error("light.far", QStringLiteral("far (%1) must be greater than near (%2)")
                               .arg(formatNumber(s.light.farPlane), formatNumber(s.light.nearPlane)));

    if ((s.light.type == LightType::Directional) != (s.light.projection == LightProjection::Ortho))
        error("light.projection", QStringLiteral("light.projection=%1 does not fit light.type=%2; a directional light is ortho, spot and point "
                                                 "lights are perspective (setting light.type sets the projection)")
                                      .arg(toString(s.light.projection), toString(s.light.type)));
    if (s.shadow.cascades > 1 && s.light.type != LightType::Directional)
        error("shadow.cascades", QStringLiteral("cascades split a directional light's map; with light.type=%1 set shadow.cascades=1")
                                     .arg(toString(s.light.type)));
    if (const ShadowStorageLimits& storage = shadowStorageLimits(shadowTechnique(s.filter.mode).map);
        usesShadowViews(s) && !storage.refusedWithViews.isEmpty() && settingValue(s, storage.refusedWithViews) == u"true")
        error(storage.refusedWithViews.toUtf8().constData(), storage.reason);
    if (s.shadow.virtualMap) {
        const auto refuse = [&](const char* key, const QString& why) {
            error(key, QStringLiteral("%1 (shadow.virtual=true); %2").arg(why, QStringLiteral("set shadow.virtual=false to use it")));
        };
        const ShadowTechnique& technique = shadowTechnique(s.filter.mode);
        const std::optional<double> reach = technique.tapReach(s.filter);
        if (s.light.type != LightType::Directional)
            refuse("light.type", QStringLiteral("virtual shadow maps are clipmaps of a directional light, not of a %1 light").arg(toString(s.light.type)));
        else if (s.shadow.cascades > 1)
            refuse("shadow.cascades", QStringLiteral("a virtual map replaces cascades: its clipmap levels give each pixel its own texel size; set shadow.cascades=1"));
        else if (s.light.warp != LightWarp::None)
            refuse("light.warp", QStringLiteral("a virtual map's pages are plain ortho views; set light.warp=none"));
        else if (s.light.fit == LightFit::Manual)
            refuse("light.fit", QStringLiteral("a virtual map's coarsest level covers the whole scene, not a manual volume; set light.fit=scene"));
        else if (technique.map == ShadowMapKind::Moments)
            refuse("filter.mode", QStringLiteral("%1 filters a moments map, and a virtual map stores depth pages").arg(toString(s.filter.mode)));
        else if (!reach)
            refuse("filter.mode", QStringLiteral("%1 may read anywhere in the map, beyond a page and its border").arg(toString(s.filter.mode)));
        else if (*reach + s.bias.normal > kVirtualPageBorder)
            refuse(s.bias.normal > 0.0 ? "bias.normal" : "filter.mode",
                   QStringLiteral("the taps (%1 texels) and the normal offset (%2 texels) reach past a page's border of %3 texels; "
                                  "choose a smaller kernel, radius or bias.normal")
                       .arg(formatNumber(*reach), formatNumber(s.bias.normal)).arg(kVirtualPageBorder));
        else if (s.filter.earlyOut && technique.penumbraOnly)
            refuse("filter.early_out", QStringLiteral("penumbra-only filtering reads a min/max mip of one map, not of pages; set filter.early_out=false"));
    }
    if (s.shadow.cascades > 1 && s.light.fit == LightFit::Manual)
        error("shadow.cascades", QStringLiteral("cascades are fitted to the camera's view; set light.fit=scene or shadow.cascades=1"));

    if (s.bias.space == BiasSpace::Depth) {
        // A depth-unit bias above half the depth range pushes every receiver through its casters.
        for (const auto& [key, value] : {std::pair{"bias.slope", s.bias.slope}, std::pair{"bias.min", s.bias.min}}) {
            if (value > 0.5)
                error(key, QStringLiteral("%1 is more than half the depth range; in depth units (bias.space=depth) it must be in [0, 0.5], "
                                          "or choose bias.space=world")
                               .arg(formatNumber(value)));
        }
    }

    if (errors.empty() && s.light.fit == LightFit::Manual && s.light.projection == LightProjection::Perspective
        && s.map.format == DepthFormat::Depth24 && s.light.farPlane / s.light.nearPlane > 1e5)
        warnings.push_back({SettingsIssue::Severity::Warning, QStringLiteral("light.near"),
                            QStringLiteral("far/near = %1 leaves a 24-bit depth map almost no precision far away; raise light.near or use map.format=depth32f")
                                .arg(formatNumber(s.light.farPlane / s.light.nearPlane))});
    if (errors.empty() && s.light.warp == LightWarp::Lispsm && s.light.type != LightType::Directional)
        warnings.push_back({SettingsIssue::Severity::Warning, QStringLiteral("light.warp"),
                            QStringLiteral("light.warp=lispsm warps a directional light's map; a %1 light's map is drawn unwarped (set light.warp=none)")
                                .arg(toString(s.light.type))});
    if (errors.empty() && s.filter.mode == FilterMode::PcfOptimized && optimizedPcfKernel(s.filter) != s.filter.kernel)
        warnings.push_back({SettingsIssue::Severity::Warning, QStringLiteral("filter.kernel"),
                            QStringLiteral("pcf-optimized has kernels of 3, 5 and 7 texels; %1 is used for filter.kernel=%2 (filter.mode=pcf has every odd width)")
                                .arg(optimizedPcfKernel(s.filter)).arg(s.filter.kernel)});
    if (errors.empty() && isMomentTechnique(s.filter.mode)) {
        const double limit = maxExponent(s.filter.mode, s.moments.format);
        for (const auto& [key, value, used] : {std::tuple{"filter.exponent_positive", s.filter.positiveExponent, usesParameter(s.filter, QStringLiteral("filter.exponent_positive"))},
                                               std::tuple{"filter.exponent_negative", s.filter.negativeExponent, usesParameter(s.filter, QStringLiteral("filter.exponent_negative"))}}) {
            if (used && value > limit)
                warnings.push_back({SettingsIssue::Severity::Warning, QString::fromLatin1(key),
                                    QStringLiteral("%1 does not fit moments.format=%2 for %3: %4 is used; choose moments.format=32 for larger exponents")
                                        .arg(formatNumber(value), toString(s.moments.format), toString(s.filter.mode), QString::number(limit, 'f', 2))});
        }
    }
    errors.insert(errors.end(), warnings.begin(), warnings.end());
    return errors;
}

void ensureValid(const Settings& settings)
{
    for (const SettingsIssue& issue : validate(settings)) {
        if (issue.severity == SettingsIssue::Severity::Error)
            throw SettingsError(issue.key, issue.message);
    }
}

} // namespace shadowlab
