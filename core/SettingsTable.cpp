#include "SettingKinds.h"
#include "SettingsEntries.h"
#include "SettingsSceneKeys.h"

#include "Limits.h"
#include "MessageText.h"
#include "MomentMath.h"
#include "SceneNames.h"
#include "SettingsError.h"
#include "ShadowTechnique.h"

#include <QFileInfo>

// The schema: one entry per key, each saying what it is, what it does, what it allows and how
// the dock shows it, in designated initialisers. Everything else (the command line, JSON files,
// validation, the dock, docs/settings.md) reads this table.
namespace shadowlab {

using namespace settings;

namespace {

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
const QStringList kBlurAtNames{QStringLiteral("auto"), QStringLiteral("lookup"), QStringLiteral("map")};
const QStringList kShadingNames{QStringLiteral("phong"), QStringLiteral("blinn-phong")};
const QStringList kRasteriserNames{QStringLiteral("auto"), QStringLiteral("software"), QStringLiteral("hardware")};
const QStringList kCacheNames{QStringLiteral("off"), QStringLiteral("static"), QStringLiteral("pages"), QStringLiteral("every-n"),
                              QStringLiteral("on-demand")};

// The dock's groups (settingGroups() lists them in order).
constexpr QLatin1String kLight("Light"), kShadowMap("Shadow map"), kBias("Bias"), kFiltering("Filtering"), kMomentsMap("Moments map"),
    kContact("Contact shadows"), kShading("Shading"), kReference("Reference"), kCamera("Camera"), kScene("Scene"),
    kRasteriser("Rasteriser");

// light.type and light.projection keep each other consistent: a file that names only the
// projection (as older files do) gets the type it meant.
Entry lightTypeKey(const SettingPresentation& look)
{
    return choice<LightType>(
        {.key = "light.type",
         .help = "directional: a direction (sun), ortho map or cascades; spot: a position with a cone (light.fov, light.falloff), unlit "
                 "outside it; point: a position casting every way through six cube faces, rendered only where they see a receiver; sets "
                 "light.projection",
         .look = look},
        kLightTypeNames, [](auto& s) -> auto& { return s.light.type; },
        [](Settings& s) {
            s.light.projection = s.light.type == LightType::Directional ? LightProjection::Ortho : LightProjection::Perspective;
        });
}

Entry projectionKey(const SettingPresentation& look)
{
    return choice<LightProjection>(
        {.key = "light.projection",
         .help = "Ortho for a directional light (sun), perspective for a spot or point light; follows light.type (setting it chooses "
                 "directional or, from a directional light, spot)",
         .look = look},
        kProjectionNames, [](auto& s) -> auto& { return s.light.projection; },
        [](Settings& s) {
            if (s.light.projection == LightProjection::Ortho)
                s.light.type = LightType::Directional;
            else if (s.light.type == LightType::Directional)
                s.light.type = LightType::Spot;
        });
}

Entry filterModeKey(const SettingPresentation& look)
{
    QStringList parts;
    for (const ShadowTechnique& t : shadowTechniques())
        parts << t.help;
    const QByteArray help = QStringLiteral("Shadow filter: %1").arg(parts.join(QStringLiteral("; "))).toUtf8();
    return choice<FilterMode>({.key = "filter.mode", .help = help.constData(), .look = look}, kFilterNames,
                              [](auto& s) -> auto& { return s.filter.mode; });
}

// A technique's parameter, typed and ranged as the technique table says, its whole range on the slider.
Entry parameterKey(const TechniqueParameter& p)
{
    const QByteArray key = p.key.toLatin1();    // copied into the entry
    const QByteArray help = p.help.toUtf8();
    const bool whole = std::holds_alternative<int FilterSettings::*>(p.field);
    const KeySpec spec{.key = key.constData(),
                       .range = {.lo = p.minimum, .hi = p.maximum},
                       .oddOnly = p.oddOnly,
                       .help = help.constData(),
                       .look = {.label = p.label, .unit = p.unit, .decimals = whole ? 0 : p.decimals, .sliderLow = p.minimum,
                                .sliderHigh = p.maximum, .group = kFiltering}};
    if (whole)
        return settings::whole(spec, [m = std::get<int FilterSettings::*>(p.field)](auto& s) -> auto& { return s.filter.*m; });
    return number(spec, [m = std::get<double FilterSettings::*>(p.field)](auto& s) -> auto& { return s.filter.*m; });
}

// The blur width: 0 for none or an odd tap count, so the kernel centres on the texel.
Entry blurKey(const SettingPresentation& look)
{
    const QString k = QStringLiteral("moments.blur");
    const QString rangeText = QStringLiteral("0 | odd in [1, %1]").arg(kMaxMomentBlur);
    const KeySpec spec{.key = "moments.blur",
                       .help = "Separable Gaussian blur of the moments map, its width in texels (moment techniques): wider "
                               "softens the penumbra and hides aliasing for more reads (moments.blur_at says where), and "
                               "spreads light bleeding further; 0 leaves the map as rendered",
                       .look = look};
    auto check = [](int v) -> std::optional<QString> {
        if (v < 0 || v > kMaxMomentBlur || (v != 0 && v % 2 == 0))
            return QStringLiteral("%1 is not allowed; use 0 (no blur) or an odd width in [1, %2], e.g. 3 or 7").arg(v).arg(kMaxMomentBlur);
        return std::nullopt;
    };
    return {describe(spec, "integer", rangeText, 0.0, double(kMaxMomentBlur)),
            [](const Settings& s) { return QString::number(s.moments.blur); },
            [check, k, rangeText](Settings& s, const QString& v) {
                const int value = parseWholeNumber(k, v, rangeText);
                if (auto problem = check(value))
                    throw SettingsError(k, *problem);
                s.moments.blur = value;
            },
            [check](const Settings& s) { return check(s.moments.blur); }};
}

// Where the light is, what kind it is and its volume as set.
void lightPlacementKeys(std::vector<Entry>& e)
{
    e.push_back(point({.key = "light.position",
                       .help = "Where the light is; with an ortho light only its direction to the target matters",
                       .look = {.label = QStringLiteral("Position"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -10.0, .sliderHigh = 10.0, .group = kLight}},
                      [](auto& s) -> auto& { return s.light.position; }));
    e.push_back(point({.key = "light.target",
                       .help = "The point the light looks at; the centre of the shadow map",
                       .look = {.label = QStringLiteral("Target"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -5.0, .sliderHigh = 5.0, .group = kLight}},
                      [](auto& s) -> auto& { return s.light.target; }));
    e.push_back(lightTypeKey({.label = QStringLiteral("Type"), .group = kLight}));
    e.push_back(projectionKey({.label = QStringLiteral("Projection"), .group = kLight}));
    e.push_back(number({.key = "light.falloff",
                        .range = {.lo = 0.0, .hi = 1.0},
                        .help = "Spot light: share of the cone's half-angle (light.fov) over which the light fades to nothing at the rim; 0 is a hard edge",
                        .look = {.label = QStringLiteral("Cone falloff"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 1.0, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.falloff; }));
    e.push_back(number({.key = "light.extent",
                        .range = {.lo = 0.0, .hi = 1e6, .loOpen = true},
                        .help = "Ortho half-size in world units: larger covers more of the scene with coarser texels (blockier, more acne)",
                        .look = {.label = QStringLiteral("Extent"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = 0.5, .sliderHigh = 30.0, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.extent; }));
    e.push_back(number({.key = "light.fov",
                        .range = {.lo = 0.0, .hi = 180.0, .loOpen = true, .hiOpen = true},
                        .help = "Perspective light's full angle in degrees: wider covers more with coarser texels",
                        .look = {.label = QStringLiteral("Field of view"), .unit = QStringLiteral("°"), .decimals = 1, .sliderLow = 10.0, .sliderHigh = 170.0, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.fov; }));
    e.push_back(number({.key = "light.near",
                        .range = {.lo = -1e7, .hi = 1e7},
                        .help = "Light near plane in world units (> 0 for perspective): pushing it out buys depth precision, casters before it are clamped",
                        .look = {.label = QStringLiteral("Near"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -10.0, .sliderHigh = 20.0, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.nearPlane; }));
    e.push_back(number({.key = "light.far",
                        .range = {.lo = -1e7, .hi = 1e7},
                        .help = "Light far plane in world units: beyond it everything is lit; a tight far plane buys depth precision",
                        .look = {.label = QStringLiteral("Far"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = 0.5, .sliderHigh = 60.0, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.farPlane; }));
    e.push_back(number({.key = "light.radius",
                        .range = {.lo = 0.0, .hi = 100.0},
                        .help = "Radius of the disk light the area reference traces (world units): the soft shadow filtered modes are measured against",
                        .look = {.label = QStringLiteral("Light radius"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.0, .sliderHigh = 2.0, .group = kReference}},
                       [](auto& s) -> auto& { return s.reference.lightRadius; }));
}

// How the light's volume is fitted to the scene and the camera.
void lightFitKeys(std::vector<Entry>& e)
{
    e.push_back(choice<LightFit>({.key = "light.fit",
                                  .help = "scene: shrink the light volume (extent or fov, near, far) to what casts onto what the camera sees, for smaller texels and finer depth; manual: use it as set",
                                  .look = {.label = QStringLiteral("Volume"), .group = kLight}},
                                 kFitNames,
                                 [](auto& s) -> auto& { return s.light.fit; }));
    e.push_back(toggle({.key = "light.stabilize",
                        .help = "Snap the fitted volume to whole texels and coarse size steps: no shimmer and no shadow-pass redraw on small camera moves, at slightly larger texels",
                        .look = {.label = QStringLiteral("Stabilise the fitted volume"), .group = kLight}},
                       [](auto& s) -> auto& { return s.light.stabilize; }));
    e.push_back(choice<LightWarp>({.key = "light.warp",
                                   .help = "Directional lights: none, or lispsm (light-space perspective shadow maps): the map warped by a perspective "
                                           "across it, so receivers near the camera get more texels and far ones fewer; no warp where the camera looks "
                                           "along the light, and a new map whenever the camera moves",
                                   .look = {.label = QStringLiteral("Warp"), .group = kLight}},
                                  kWarpNames,
                                  [](auto& s) -> auto& { return s.light.warp; }));
    e.push_back(number({.key = "light.warp_scale",
                        .range = {.lo = 0.05, .hi = 100.0},
                        .help = "With light.warp=lispsm: the warp's near distance as a multiple of Wimmer's optimum; below 1 a stronger warp "
                                "(finer near the camera, coarser far away), above 1 a weaker one",
                        .look = {.label = QStringLiteral("Warp scale"), .decimals = 2, .sliderLow = 0.1, .sliderHigh = 10.0, .logarithmic = true, .group = kLight}},
                       [](auto& s) -> auto& { return s.light.warpScale; }));
}

// The depth map and its bias against acne and peter panning.
void mapKeys(std::vector<Entry>& e)
{
    e.push_back(whole({.key = "map.size",
                       .range = {.lo = 16, .hi = kMaxImageSide},
                       .help = "Shadow map texels per side: more texels, sharper edges and less acne, at more memory and shadow-pass time",
                       .look = {.label = QStringLiteral("Size"), .unit = QStringLiteral(" px"), .sliderLow = 64.0, .sliderHigh = 8192.0, .logarithmic = true, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.map.size; }));
    e.push_back(choice<DepthFormat>({.key = "map.format",
                                     .help = "Depth texture format: 32-bit float keeps precision with far-away near/far ratios",
                                     .look = {.label = QStringLiteral("Depth format"), .group = kShadowMap}},
                                    kFormatNames,
                                    [](auto& s) -> auto& { return s.map.format; }));
    e.push_back(whole({.key = "map.slices",
                       .range = {.lo = 1, .hi = 8},
                       .help = "Redraws of a depth24 map between clears: each writes a nearer 1/n of the depth range, so what earlier ones left reads lit, as cleared texels do (the same shadows, one clear in n); "
                               "costs log2(n) of the 24 bits; 1 clears every redraw. Ortho maps and a point light's faces (while a slice keeps their depth steps under an eighth of a texel); spot and warped maps, cascades, virtual pages and depth32f clear every time. "
                               "A software rasteriser's optimisation: on under rasteriser.profile=software (auto on llvmpipe), every draw clears on a GPU",
                       .look = {.label = QStringLiteral("Slices"), .sliderLow = 1.0, .sliderHigh = 8.0, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.map.slices; }));
    e.push_back(number({.key = "map.slice_coverage",
                        .range = {.lo = 0.0, .hi = 1.0},
                        .help = "Slices (map.slices) only while the casters may cover at most this share of the map (the area of their reach): a draw into a slice reads each texel "
                                "it covers from memory, where after a clear it finds it in the cache, so past it a clear is cheaper; 1 slices whatever they cover, 0 never. "
                                "A point light's faces, whose clears are scissored and as dear as a slice, slice at any coverage but 0",
                        .look = {.label = QStringLiteral("Slice coverage"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 1.0, .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.map.sliceCoverage; }));
    e.push_back(choice<BiasSpace>({.key = "bias.space",
                                   .help = "Unit of bias.slope and bias.min: world units along the ray to the light (same offset for any near/far, map size or fit), texels of the map (follows the resolution), or depth-buffer units (the classic form, whose world offset grows with far - near)",
                                   .look = {.label = QStringLiteral("Unit"), .group = kBias}},
                                  kBiasSpaceNames,
                                  [](auto& s) -> auto& { return s.bias.space; }));
    e.push_back(number({.key = "bias.slope",
                        .range = {.lo = 0.0, .hi = 100.0},
                        .help = "Slope-scaled bias, times (1 - N.L), in the unit of bias.space (world units, texels, or depth units <= 0.5): too little shows acne on lit slopes, too much detaches shadows (peter panning)",
                        .look = {.label = QStringLiteral("Slope"), .decimals = 4, .sliderLow = 0.0, .sliderHigh = 0.5, .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.slope; }));
    e.push_back(number({.key = "bias.min",
                        .range = {.lo = 0.0, .hi = 100.0},
                        .help = "Minimum bias, in the unit of bias.space (world units, texels, or depth units <= 0.5): removes acne on surfaces facing the light, too much makes shadows leak at contacts",
                        .look = {.label = QStringLiteral("Minimum"), .decimals = 4, .sliderLow = 0.0, .sliderHigh = 0.1, .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.min; }));
    e.push_back(number({.key = "bias.normal",
                        .range = {.lo = 0.0, .hi = 8.0},
                        .help = "Normal-offset bias in shadow-map texels: looks the shadow up from a point moved off the surface, against acne at grazing angles without detaching contact shadows as much as depth bias",
                        .look = {.label = QStringLiteral("Normal offset"), .unit = QStringLiteral(" texels"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 8.0, .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.normal; }));
    e.push_back(toggle({.key = "bias.cull_front",
                        .help = "Render back faces into the shadow map: removes acne on closed lit faces, can leak light where thin casters touch",
                        .look = {.label = QStringLiteral("Cull front faces in the shadow pass"), .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.cullFront; }));
    e.push_back(number({.key = "bias.polygon_factor",
                        .range = {.lo = -16.0, .hi = 16.0},
                        .help = "glPolygonOffset factor in the shadow pass: hardware slope bias, against acne at the cost of peter panning",
                        .look = {.label = QStringLiteral("Offset factor"), .decimals = 2, .sliderLow = -4.0, .sliderHigh = 8.0, .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.polygonFactor; }));
    e.push_back(number({.key = "bias.polygon_units",
                        .range = {.lo = -10000.0, .hi = 10000.0},
                        .help = "glPolygonOffset units in the shadow pass: constant hardware bias in depth-buffer steps",
                        .look = {.label = QStringLiteral("Offset units"), .sliderLow = -500.0, .sliderHigh = 5000.0, .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.polygonUnits; }));
    e.push_back(toggle({.key = "bias.receiver_plane",
                        .help = "Wide filters (pcf, poisson, pcss) compare each tap against the receiver's plane (its depth gradient in shadow-map space): no over-darkening of lit slopes by wide kernels with a small bias, but acne or leaks on curved receivers and at silhouettes, where the gradient is wrong",
                        .look = {.label = QStringLiteral("Receiver-plane depth for wide filters"), .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.receiverPlane; }));
    e.push_back(toggle({.key = "bias.footprint",
                        .help = "Each lookup's bias covers the texels it reads: the lookup moves off the surface by half a texel times "
                                "sin(theta) along the normal, and each tap of a wide filter (pcf, pcf64, poisson, pcss, dpcf) compares "
                                "against a depth grown with its distance by the receiver's slope, so no filter shows acne or moire on "
                                "lit slopes and curved meshes; off: one bias for every tap, the textbook form (depth-compare filters only)",
                        .look = {.label = QStringLiteral("Bias follows the filter's footprint"), .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.footprint; }));
    e.push_back(toggle({.key = "bias.skip_floors",
                        .help = "Leave out of the shadow pass a floor the light is above (a flat object with every other object on "
                                "the side it faces, such as a model's ground): it can shadow nothing there, so leaving it out is "
                                "exact and it cannot shadow itself (no acne or moire on it); evsm4 and msm, which need it in their "
                                "moments map, draw it only around the casters; off: it is drawn like any caster",
                        .look = {.label = QStringLiteral("Leave floors out of the shadow pass"), .group = kBias}},
                       [](auto& s) -> auto& { return s.bias.skipFloors; }));
}

// The filter, its parameters and the moments map the moment filters read.
void filterKeys(std::vector<Entry>& e)
{
    e.push_back(filterModeKey({.label = QStringLiteral("Filter"), .group = kFiltering}));
    for (const TechniqueParameter& parameter : techniqueParameters())
        e.push_back(parameterKey(parameter));
    e.push_back(toggle({.key = "filter.early_out",
                        .help = "Penumbra-only filtering: pcf, pcf-optimized, poisson, pcss and dpcf skip their taps where a min/max depth mip of the map shows the whole footprint lit or shadowed; the same image, less time outside penumbrae, a mip built with each shadow pass (pcss and dpcf build it anyway, for their blocker search)",
                        .look = {.label = QStringLiteral("Filter only penumbrae"), .group = kFiltering}},
                       [](auto& s) -> auto& { return s.filter.earlyOut; }));
    e.push_back(choice<MomentFormat>({.key = "moments.format",
                                      .help = "Bits per channel of the moments map (moment techniques): 16 halves memory and bandwidth, but "
                                              "holds only small exponents (evsm <= 5.54, esm <= 11.08) and needs a larger filter.moment_bias; "
                                              "msm then stores Peters and Klein's optimised quantisation",
                                      .look = {.label = QStringLiteral("Format"), .group = kMomentsMap}},
                                     kMomentFormatNames,
                                     [](auto& s) -> auto& { return s.moments.format; }));
    e.push_back(blurKey({.label = QStringLiteral("Blur"), .unit = QStringLiteral(" texels"), .sliderLow = 0.0, .sliderHigh = 31.0, .group = kMomentsMap}));
    e.push_back(choice<MomentBlurAt>({.key = "moments.blur_at",
                                      .help = "Where moments.blur runs (moment techniques), the same kernel either way: map is a pass over "
                                              "every texel the casters reach, two reads of its width each; lookup applies it in the lit "
                                              "pass to the map as drawn, (width + 1)^2 / 4 bilinear reads for each pixel that looks up and "
                                              "none for texels no pixel reads; auto: lookup up to a width of 5, map otherwise; always "
                                              "map with mipmaps (built from the blurred map) or anisotropy above 1",
                                      .look = {.label = QStringLiteral("Blur runs in"), .group = kMomentsMap}},
                                     kBlurAtNames,
                                     [](auto& s) -> auto& { return s.moments.blurAt; }));
    e.push_back(toggle({.key = "moments.mipmaps",
                        .help = "Mipmaps of the moments map (moment techniques), built after each moments pass: trilinear lookups keep "
                                "distant and grazing shadows smooth instead of aliased, at the cost of a mip build and blurrier far shadows",
                        .look = {.label = QStringLiteral("Mipmaps"), .group = kMomentsMap}},
                       [](auto& s) -> auto& { return s.moments.mipmaps; }));
    e.push_back(whole({.key = "moments.anisotropy",
                       .range = {.lo = 1, .hi = 16},
                       .help = "Anisotropic filtering of the moments map (moment techniques), 1 for off: sharper shadows on receivers seen "
                               "at grazing angles for more texture reads; capped at what the driver offers",
                       .look = {.label = QStringLiteral("Anisotropy"), .sliderLow = 1.0, .sliderHigh = 16.0, .group = kMomentsMap}},
                      [](auto& s) -> auto& { return s.moments.anisotropy; }));
    e.push_back(whole({.key = "moments.view",
                       .range = {.lo = 1, .hi = 4},
                       .help = "Which stored moment the depth-map view shows for a moment technique: 1 is depth (unwarped for esm and "
                               "evsm, linear for a perspective light), 2 to 4 the higher ones as stored (exponential ones on a log scale); "
                               "for vsm and evsm2 3, for esm 2, is the share of the texel casters cover",
                       .look = {.label = QStringLiteral("Moment shown"), .sliderLow = 1.0, .sliderHigh = 4.0, .group = kMomentsMap}},
                      [](auto& s) -> auto& { return s.moments.view; }));
}

// Shadows on or off, and the views a directional light's map is cut into.
void shadowKeys(std::vector<Entry>& e)
{
    e.push_back(toggle({.key = "shadow.enabled",
                        .help = "Shadows on or off: off skips the shadow pass entirely",
                        .look = {.label = QStringLiteral("Shadows"), .group = kShading}},
                       [](auto& s) -> auto& { return s.shadow.enabled; }));
    e.push_back(whole({.key = "shadow.cascades",
                       .range = {.lo = 1, .hi = kMaxCascades},
                       .help = "Cascaded shadow maps for a directional light: the view up to shadow.distance split into this many slices, each with a map.size map of its own (more texels near the camera); 1 fits one map to the whole view",
                       .look = {.label = QStringLiteral("Cascades"), .sliderLow = 1.0, .sliderHigh = 4.0, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.shadow.cascades; }));
    e.push_back(choice<CascadeSplit>({.key = "shadow.split",
                                      .help = "Where cascades split: uniform (equal depth slices, coarse near the camera), logarithmic (equal ratios, tiny first slices) or practical (a blend by shadow.split_lambda)",
                                      .look = {.label = QStringLiteral("Cascade split"), .group = kShadowMap}},
                                     kSplitNames,
                                     [](auto& s) -> auto& { return s.shadow.split; }));
    e.push_back(choice<DepthFit>({.key = "shadow.depth_fit",
                                  .help = "With cascades: the depth range they split, distance (the camera's near plane to shadow.distance) or "
                                          "sdsm (sample-distribution shadow maps: from the nearest to the farthest pixel drawn, up to "
                                          "shadow.distance, read from a depth prepass of the frame; more texels where the view has receivers)",
                                  .look = {.label = QStringLiteral("Cascade depth range"), .group = kShadowMap}},
                                 kDepthFitNames,
                                 [](auto& s) -> auto& { return s.shadow.depthFit; }));
    e.push_back(number({.key = "shadow.split_lambda",
                        .range = {.lo = 0.0, .hi = 1.0},
                        .help = "Practical split: 0 uniform, 1 logarithmic",
                        .look = {.label = QStringLiteral("Split λ"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 1.0, .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.splitLambda; }));
    e.push_back(number({.key = "shadow.distance",
                        .range = {.lo = 0.0, .hi = 1e7, .loOpen = true},
                        .help = "With cascades: world units from the camera up to which receivers get shadows; beyond it they are lit",
                        .look = {.label = QStringLiteral("Shadow distance"), .unit = QStringLiteral(" wu"), .decimals = 1, .sliderLow = 1.0, .sliderHigh = 2000.0, .logarithmic = true, .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.distance; }));
    e.push_back(number({.key = "shadow.blend",
                        .range = {.lo = 0.0, .hi = 0.5},
                        .help = "With cascades: share of each cascade's depth, at its far end, over which it fades into the next (hides the seam's change of resolution)",
                        .look = {.label = QStringLiteral("Cascade blend"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 0.5, .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.blend; }));
    e.push_back(toggle({.key = "shadow.show_cascades",
                        .help = "Tint receivers by the cascade (red, green, blue, yellow) or cube face they read: where each map's texels go",
                        .look = {.label = QStringLiteral("Tint by cascade or cube face"), .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.showCascades; }));
    e.push_back(toggle({.key = "shadow.cutouts",
                        .help = "Cut-out casters (glTF alphaMode MASK: leaves, fences) cast through their holes, a texture lookup and discard "
                                "in the shadow pass; off casts them as solid as their quads, as a renderer that ignores the mask "
                                "(the eye and the reference still see the holes, so the report shows what ignoring it costs)",
                        .look = {.label = QStringLiteral("Cut-out casters"), .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.cutouts; }));
}

// Virtual shadow maps.
void virtualMapKeys(std::vector<Entry>& e)
{
    e.push_back(toggle({.key = "shadow.virtual",
                        .help = "Virtual shadow maps (directional lights): clipmap levels of 16384² texels cut into 128² pages; each visible "
                                "pixel asks for the page of the level whose texel covers at most one screen pixel, and only those pages are "
                                "drawn, into a pool of shadow.virtual_pool² pages, and kept until the light or the scene changes; "
                                "replaces map.size and cascades",
                        .look = {.label = QStringLiteral("Virtual shadow map"), .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.virtualMap; }));
    e.push_back(whole({.key = "shadow.virtual_pool",
                       .range = {.lo = 4, .hi = 64},
                       .help = "With shadow.virtual: pages per side of the physical pool (each 128² texels and a 4-texel border), the "
                               "memory budget; when a view asks for more pages, the finest ones are coarsened a level, with a warning",
                       .look = {.label = QStringLiteral("Page pool (per side)"), .unit = QStringLiteral(" pages"), .sliderLow = 4.0, .sliderHigh = 64.0, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.shadow.virtualPool; }));
    e.push_back(whole({.key = "shadow.virtual_levels",
                       .range = {.lo = 1, .hi = 16},
                       .help = "With shadow.virtual: clipmap levels; the coarsest holds the whole scene in 2 x 2 pages (256 texels "
                               "across), each finer one has half its texel, so the finest texel is the scene's width / 256 / 2^(levels - 1)",
                       .look = {.label = QStringLiteral("Clipmap levels"), .sliderLow = 1.0, .sliderHigh = 16.0, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.shadow.virtualLevels; }));
    e.push_back(whole({.key = "shadow.virtual_lod_bias",
                       .range = {.lo = 0, .hi = 4},
                       .help = "With shadow.virtual: how many levels finer than one texel per screen pixel each pixel asks for; every "
                               "level halves the texel, so a shadow edge's error shrinks to half a pixel and less, for about four "
                               "times the pages a level",
                       .look = {.label = QStringLiteral("Level bias (finer)"), .sliderLow = 0.0, .sliderHigh = 4.0, .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.shadow.virtualLodBias; }));
}

// What the shadow pass keeps between frames while casters move (renderer/ShadowCache.h).
void cacheKeys(std::vector<Entry>& e)
{
    e.push_back(choice<ShadowCachePolicy>(
        {.key = "shadow.cache",
         .help = "What the shadow pass keeps while casters move: off draws every caster of a view again; static draws the still casters once "
                 "into a copy of each view and, each frame, starts from the copy and draws only the moving casters over it (the same "
                 "pixels as off); pages keeps a virtual map's pages but those a moved caster's old or new bounds touch (the same pixels); "
                 "every-n draws the moving casters every shadow.cache_interval-th frame they move, stale between; on-demand keeps the "
                 "map until asked (View > Redraw cached shadows), stale. A moving light or a changed setting draws everything",
         .look = {.label = QStringLiteral("Cache"), .group = kShadowMap}},
        kCacheNames, [](auto& s) -> auto& { return s.shadow.cache; }));
    e.push_back(whole({.key = "shadow.cache_interval",
                       .range = {.lo = 1, .hi = 600},
                       .help = "With shadow.cache=every-n: the frames of moving casters from one redraw of them to the next; the shadows "
                               "between are those of the last redraw",
                       .look = {.label = QStringLiteral("Redraw every"), .unit = QStringLiteral(" frames"), .sliderLow = 1.0, .sliderHigh = 60.0,
                                .group = kShadowMap}},
                      [](auto& s) -> auto& { return s.shadow.cacheInterval; }));
    e.push_back(toggle({.key = "shadow.force_invalidate",
                        .help = "Draws every view (or virtual page) every frame, as a moving light does: what any shadow.cache costs at its "
                                "worst (a moving sun), for benchmarks, as Unreal's ForceInvalidateDirectional",
                        .look = {.label = QStringLiteral("Redraw every frame"), .group = kShadowMap}},
                       [](auto& s) -> auto& { return s.shadow.forceInvalidate; }));
}

// Contact shadows, shading and the camera.
void viewKeys(std::vector<Entry>& e)
{
    e.push_back(toggle({.key = "contact.enabled",
                        .help = "Contact shadows: a short march toward the light over the camera's depth of the casters (front and back faces), "
                                "combined with the map's shadow as the smaller visibility; brings back the shadow a bias lifts off contacts "
                                "(peter panning), for two depth prepasses and 2 x contact.steps lookups a pixel; finds only casters on screen",
                        .look = {.label = QStringLiteral("Contact shadows"), .group = kContact}},
                       [](auto& s) -> auto& { return s.contact.enabled; }));
    e.push_back(number({.key = "contact.length",
                        .range = {.lo = 0.0, .hi = 1e6, .loOpen = true},
                        .help = "World units the contact march goes toward the light: longer finds casters farther from the receiver, with "
                                "coarser steps and more false shadow behind thin objects",
                        .look = {.label = QStringLiteral("Length"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.01, .sliderHigh = 10.0, .logarithmic = true, .group = kContact}},
                       [](auto& s) -> auto& { return s.contact.length; }));
    e.push_back(whole({.key = "contact.steps",
                       .range = {.lo = 1, .hi = 64},
                       .help = "Depth lookups of the contact march: more steps miss fewer thin casters, linearly more time",
                       .look = {.label = QStringLiteral("Steps"), .sliderLow = 1.0, .sliderHigh = 64.0, .group = kContact}},
                      [](auto& s) -> auto& { return s.contact.steps; }));
    e.push_back(number({.key = "contact.thickness",
                        .range = {.lo = 0.0, .hi = 1e6, .loOpen = true},
                        .help = "World units a caster may extend behind the front face the camera sees, at most; within it the march "
                                "is in shadow only between a caster's front and back faces, so light passing behind a caster stays lit. "
                                "It bounds casters with no back faces (open meshes): too thin misses the inside of thick ones",
                        .look = {.label = QStringLiteral("Thickness"), .unit = QStringLiteral(" wu"), .decimals = 3, .sliderLow = 0.001, .sliderHigh = 10.0, .logarithmic = true, .group = kContact}},
                       [](auto& s) -> auto& { return s.contact.thickness; }));
    e.push_back(choice<ShadingModel>({.key = "shading.model",
                                      .help = "Specular model: Blinn-Phong (half vector) or Phong (reflection vector)",
                                      .look = {.label = QStringLiteral("Specular"), .group = kShading}},
                                     kShadingNames,
                                     [](auto& s) -> auto& { return s.shading.model; }));
    e.push_back(toggle({.key = "shading.texel_density",
                        .help = "Tint the scene by screen pixels per shadow-map texel: blue under 1 (the map is finer than the screen), green about 1 to 2, "
                                "yellow to red from 4 up (blocky edges); shadows and measurements are unchanged",
                        .look = {.label = QStringLiteral("Texel density overlay"), .group = kShading}},
                       [](auto& s) -> auto& { return s.shading.texelDensity; }));
    e.push_back(toggle({.key = "shading.shadow_only",
                        .help = "Show the shadow term alone, as engines' debug views do: white where lit, black where shadowed, grey between "
                                "(a filter's partial shadow, a moiré), dark blue where a surface faces away from the light; no textures or "
                                "lighting; measurements are unchanged",
                        .look = {.label = QStringLiteral("Shadow only"), .group = kShading}},
                       [](auto& s) -> auto& { return s.shading.shadowOnly; }));
    e.push_back(point({.key = "camera.position",
                       .help = "Where the viewer is",
                       .look = {.label = QStringLiteral("Position"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -20.0, .sliderHigh = 20.0, .group = kCamera}},
                      [](auto& s) -> auto& { return s.camera.position; }));
    e.push_back(point({.key = "camera.target",
                       .help = "The point the viewer looks at",
                       .look = {.label = QStringLiteral("Target"), .unit = QStringLiteral(" wu"), .decimals = 2, .sliderLow = -5.0, .sliderHigh = 5.0, .group = kCamera}},
                      [](auto& s) -> auto& { return s.camera.target; }));
    e.push_back(number({.key = "camera.fov",
                        .range = {.lo = 1.0, .hi = 170.0},
                        .help = "Camera vertical field of view in degrees",
                        .look = {.label = QStringLiteral("Field of view"), .unit = QStringLiteral("°"), .decimals = 1, .sliderLow = 10.0, .sliderHigh = 120.0, .group = kCamera}},
                       [](auto& s) -> auto& { return s.camera.fov; }));

}

std::vector<Entry> makeEntries()
{
    std::vector<Entry> e;
    e.push_back(sceneKey({.label = QStringLiteral("Preset"), .group = kScene}));
    e.push_back(objectSwitchKey("objects.no_cast", "Objects of the scene that cast no shadow, by name (or #i for the i-th object), "
                                "separated by commas: what one caster's shadow costs and hides, seen by switching it off; the "
                                "reference leaves it out too", QStringLiteral("Casts a shadow"), kScene, &ObjectSwitches::noCast));
    e.push_back(objectSwitchKey("objects.no_receive", "Objects of the scene that receive no shadow, always lit and left out of "
                                "what is measured, by name (or #i), separated by commas",
                                QStringLiteral("Receives shadows"), kScene, &ObjectSwitches::noReceive));
    e.push_back(number({.key = "scene.time",
                        .range = {.lo = 0.0, .hi = kMaxSceneTime},
                        .help = "Seconds since the scene's start: where its moving objects (shapes' \"motion\", a model's node animation, "
                                "a city's vehicles) are; a still scene ignores it",
                        .look = {.label = QStringLiteral("Time"), .unit = QStringLiteral(" s"), .decimals = 2, .sliderLow = 0.0, .sliderHigh = 10.0, .group = kScene}},
                       [](auto& s) -> auto& { return s.animation.time; }));
    e.push_back(toggle({.key = "scene.play",
                        .help = "The window's clock runs: scene.time advances with the wall clock times scene.speed, looping over the clip",
                        .look = {.label = QStringLiteral("Play"), .group = kScene}},
                       [](auto& s) -> auto& { return s.animation.play; }));
    e.push_back(number({.key = "scene.speed",
                        .range = {.lo = 0.01, .hi = 100.0},
                        .help = "Scene seconds per wall-clock second while playing: below 1 slow motion",
                        .look = {.label = QStringLiteral("Speed"), .unit = QStringLiteral("×"), .decimals = 2, .sliderLow = 0.05, .sliderHigh = 4.0, .logarithmic = true, .group = kScene}},
                       [](auto& s) -> auto& { return s.animation.speed; }));
    lightPlacementKeys(e);
    lightFitKeys(e);
    mapKeys(e);
    filterKeys(e);
    shadowKeys(e);
    virtualMapKeys(e);
    cacheKeys(e);
    viewKeys(e);
    e.push_back(choice<RasteriserProfile>({.key = "rasteriser.profile",
                                           .help = "Which rasteriser the renderer's optimisations are chosen for: software (a CPU rasteriser such as llvmpipe, "
                                                   "where clears and bandwidth cost what casters do: the shadow reach's stencil masks, depth slices, "
                                                   "two moments in RGBA, a virtual map's requests read back whole), hardware (a GPU: the plain path), or auto "
                                                   "(from the driver's GL_RENDERER). The same pixels under each (msm's to within a step); only what a frame costs differs",
                                           .look = {.label = QStringLiteral("Profile"), .group = kRasteriser}},
                                          kRasteriserNames,
                                          [](auto& s) -> auto& { return s.rasteriser.profile; }));
    return e;
}

} // namespace

namespace settings {

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
    throw SettingsError::unknownKey(key, QStringLiteral("unknown setting%1").arg(didYouMean(key, keys)));
}

} // namespace settings

const QStringList& settingGroups()
{
    static const QStringList groups{kLight, kShadowMap, kBias, kFiltering, kMomentsMap, kContact, kShading, kReference, kCamera, kScene, kRasteriser};
    return groups;
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
QString toString(RasteriserProfile value) { return kRasteriserNames.value(int(value)); }
QString toString(ShadowCachePolicy value) { return kCacheNames.value(int(value)); }
QString toString(MomentFormat value) { return kMomentFormatNames.value(int(value)); }
QString toString(MomentBlurAt value) { return kBlurAtNames.value(int(value)); }

} // namespace shadowlab
