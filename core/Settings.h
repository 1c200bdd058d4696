#pragma once

#include <glm/vec3.hpp>

#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// Plain structs with their defaults, as Filament's Options: each field's range, unit and help
// are declared once, in the schema (SettingsTable.cpp), which validates them; the comments here
// say what a field means.

enum class LightProjection { Ortho, Perspective };
// Directional: a direction, an ortho map (or cascades); spot: a position with a cone and a
// perspective map; point: a position casting every way through six cube faces.
enum class LightType { Directional, Spot, Point };
enum class CascadeSplit { Uniform, Logarithmic, Practical };
// What cascades split: the camera's near plane to shadow.distance, or the view depth range of
// the pixels actually drawn (sample-distribution shadow maps, Lauritzen 2010).
enum class DepthFit { Distance, Sdsm };
enum class LightFit { Manual, Scene };
// A directional light's map warped across itself: none, or light-space perspective shadow maps
// (Wimmer 2004), which give the receivers near the camera more of the map's texels.
enum class LightWarp { None, Lispsm };
enum class DepthFormat { Depth24, Depth32F };
enum class BiasSpace { World, Texel, Depth };
enum class FilterMode { Hard, Pcf, PcfOptimized, PcfDither4, Pcf64, HwBilinear, Poisson, Pcss, Dpcf, Vsm, Evsm2, Evsm4, Msm, MsmHausdorff, Esm };
enum class MomentFormat { Rgba16F, Rgba32F };
// Where the moments blur runs: a pass over the map after the moments pass, or the lit pass's
// lookup applying the same kernel to the map as drawn; auto picks the lookup for a narrow blur
// over a map without mips.
enum class MomentBlurAt { Auto, Lookup, Map };
enum class ShadingModel { Phong, BlinnPhong };
// Which kind of rasteriser the renderer's optimisations are chosen for (RasteriserTuning): auto
// from GL_RENDERER, or forced. Frames are the same under each; only what they cost differs.
enum class RasteriserProfile { Auto, Software, Hardware };
// What the shadow pass keeps between frames while casters move (renderer/ShadowCache.h): off
// draws every caster again; static keeps a copy of the still casters' map and draws only the
// moving ones over it (exact); pages keeps a virtual map's pages but those a moved caster
// touches (exact); every-n draws moving casters every n-th frame (stale between); on-demand
// until asked (stale).
enum class ShadowCachePolicy { Off, Static, Pages, EveryN, OnDemand };

inline constexpr int kMaxCascades = 4;
// Every field carries its range in a comment; SettingsTable.cpp holds the same ranges for
// parsing and validate() enforces them, so GUI, CLI and JSON agree on what is allowed.
struct LightSettings {
    glm::dvec3 position{-2.0, 4.0, -1.0};   // world units, finite, |x| <= 1e7, != target
    glm::dvec3 target{0.0, 0.0, 0.0};       // world units, finite, |x| <= 1e7
    LightProjection projection = LightProjection::Ortho;
    double extent = 10.0;                   // ortho half-size in world units
    double fov = 90.0;                      // perspective full angle in degrees
    double nearPlane = 1.0;                 // ortho: any finite < far; perspective: > 0
    double farPlane = 7.5;                  // > near, <= 1e7
    // Scene: the volume above shrunk to what casts onto what the camera sees (LightFitting.h);
    // Manual: exactly the volume above.
    LightFit fit = LightFit::Scene;
    bool stabilize = true;                  // snap the fitted volume so camera moves neither shimmer nor redraw the map
    // light.type sets light.projection (directional: ortho; spot, point: perspective) and
    // light.projection sets light.type (ortho: directional, perspective: spot), so settings
    // files that name only the projection load as before; validate() refuses a mismatch.
    LightType type = LightType::Directional;
    double falloff = 0.2;                   // spot: share of the cone's half-angle over which light fades out at its rim
    // Directional lights (each cascade too): LiSPSM's perspective warp of the map, its strength
    // from Wimmer's optimal n times warpScale (larger: weaker, toward no warp).
    LightWarp warp = LightWarp::None;
    double warpScale = 1.0;                 // the warp's near distance as a multiple of Wimmer's optimum

    bool operator==(const LightSettings&) const = default;
};

struct MapSettings {
    int size = 2048;                        // texels per side
    DepthFormat format = DepthFormat::Depth24;
    int slices = 4;                         // redraws between clears of a depth24 map (DepthSlices::beginDraw)
    double sliceCoverage = 0.85;            // slices only while the casters may cover at most this share of the map

    bool operator==(const MapSettings&) const = default;
};

// Bias = max(slope * (1 - N.L), min): (1 - N.L) <= 1 keeps it bounded at grazing angles,
// unlike the slope * tan(theta) form. Its unit is `space`:
// - World: world units along the ray to the light, so the same setting means the same offset
//   for any near/far, map size or fitted extent (the default);
// - Texel: texels of the map (world size of one texel, at the receiver's distance for a
//   perspective light), so the offset follows the resolution, like Filament's bias;
// - Depth: depth-buffer units ([0, 1] window depth), the classic tutorial form, whose world
//   meaning grows with far - near.
// Normal offset moves the shadow lookup along the surface normal, in shadow-map texels.
struct BiasSettings {
    BiasSpace space = BiasSpace::World;
    // On the knee of `shadowlab tune` for every preset (within 0.001 % of the best misclassified
    // share, with back faces in the map): about a texel of the fitted map, small enough not to
    // detach contact shadows, large enough for open meshes whose front faces stay in the map.
    double slope = 0.01;                    // in the unit of `space`
    double min = 0.002;                     // in the unit of `space`
    double normal = 0.0;                    // texels
    // Back faces only into the shadow map: on `seed` as accurate as any bias alone and the
    // cheapest shadow pass (the single-sided ground is not drawn), so on the accuracy
    // report's Pareto front (`shadowlab report`); the classic acne demonstration turns it off.
    bool cullFront = true;
    double polygonFactor = 0.0;             // glPolygonOffset factor
    double polygonUnits = 0.0;              // glPolygonOffset units
    // Wide filters (pcf, poisson, pcss) compare each tap against the receiver's plane, from its
    // depth gradient in shadow-map space, instead of the centre's depth (pcf) or a bias grown
    // with the tap's distance (poisson, pcss): exact on planar receivers, wrong where the
    // gradient is (curved surfaces, silhouettes).
    bool receiverPlane = false;
    // Every lookup's bias covers the texels it reads, whatever the filter: the lookup moves off
    // the surface by half a texel times sin(theta) along the normal (its own texel), and each tap
    // of a wide filter compares against a depth grown with its distance by the receiver's slope.
    // Off: the textbook form, one bias for every tap (acne and moiré where a kernel is wide).
    bool footprint = true;
    // A floor (a flat object with everything else on the side it faces) under a light on that
    // side shadows nothing, so the shadow pass leaves it out: it cannot shadow itself either.
    bool skipFloors = true;

    bool operator==(const BiasSettings&) const = default;
};

struct FilterSettings {
    // One bilinear hardware-compare tap on a 2048 map: smoother and closer to the true edge
    // than 3 x 3 PCF on a 1024 map, at about two thirds of its frame time (`shadowlab bench --baseline`).
    FilterMode mode = FilterMode::HwBilinear;
    int kernel = 3;                         // odd; used by FilterMode::Pcf (PcfOptimized: 3 to 7)
    int taps = 16;                          // Poisson taps of FilterMode::Poisson, Pcss and Dpcf
    double radius = 2.5;                    // texels; used by FilterMode::Poisson
    // pcf, pcf-optimized, poisson, pcss and dpcf skip their taps where a min/max depth mip of
    // the map says the whole footprint is lit or shadowed; the image is the same. Off by
    // default: on llvmpipe the mip costs more with every shadow pass than the skipped taps save
    // (`shadowlab report`); pcss and dpcf build it anyway, for their blocker search.
    bool earlyOut = false;
    // The moment techniques (vsm, evsm2, evsm4, msm, esm), read at lookup: changing them needs
    // no new moments pass.
    double bleeding = 0.2;                  // light-bleeding reduction: visibility below it reads as shadow
    double momentBias = 1e-4;               // least variance (vsm; evsm relative to w^2) or the blend toward 0.5 (msm)
    double positiveExponent = 40.0;         // esm/evsm warp, clamped to what moments.format holds
    double negativeExponent = 5.0;          // evsm4's negative warp, clamped likewise

    bool operator==(const FilterSettings&) const = default;
};

// The moments pass of the moment techniques: what it stores and how it is prefiltered.
struct MomentSettings {
    MomentFormat format = MomentFormat::Rgba32F;
    int blur = 3;                           // separable Gaussian width in texels, odd; 0: none
    MomentBlurAt blurAt = MomentBlurAt::Auto;
    bool mipmaps = false;                   // trilinear lookups from a mip chain built after the blur
    int anisotropy = 1;                     // 1 is off; clamped to what the driver offers
    int view = 1;                           // the moment the depth-map view shows

    bool operator==(const MomentSettings&) const = default;
};

// Contact shadows: a short march toward the light over the camera's depth of the casters, the
// standard cure for the light a depth bias lets through where casters meet receivers. Combined
// with the map's shadow as the smaller visibility.
struct ContactSettings {
    bool enabled = false;
    double length = 0.3;                    // world units marched toward the light
    int steps = 12;                         // depth lookups of the march
    double thickness = 1.0;                 // world units a caster may extend behind its front face at most

    bool operator==(const ContactSettings&) const = default;
};

struct ShadowSettings {
    bool enabled = true;
    // Cascaded shadow maps for a directional light: the camera's view from its near plane to
    // `distance` split into `cascades` slices, each with a map of map.size² fitted to it (the
    // maps sit side by side in one texture). Beyond `distance` receivers are lit.
    int cascades = 1;                       // 1: one map fitted to the whole view (no distance limit)
    CascadeSplit split = CascadeSplit::Practical;
    double splitLambda = 0.75;              // practical split: 0 uniform ... 1 logarithmic
    double distance = 100.0;                // world units from the camera; used with cascades > 1
    double blend = 0.1;                     // share of each cascade blended into the next at its far end
    DepthFit depthFit = DepthFit::Distance; // used with cascades > 1
    bool showCascades = false;              // tint receivers by the cascade (or cube face) they read
    // Cut-out casters (SceneObject::alphaCutoff) cast through their holes; false casts them whole,
    // as a renderer that ignores the mask does (the eye and the reference still see the holes).
    bool cutouts = true;
    // Virtual shadow maps for a directional light (core/VirtualPages.h): clipmap levels of
    // 16384² virtual texels each, cut into pages of 128², of which only those the visible pixels
    // need are drawn, into a pool of virtualPool² physical pages, and kept while the light stays.
    bool virtualMap = false;
    // 1600 pages (Unreal's default pool holds 2048): a 1920 x 1080 view of the city at a level
    // finer asks for 1373; the 30² that match the memory of 4 cascades of 2048² coarsened 109.
    int virtualPool = 40;                   // pages per side of the physical pool
    int virtualLevels = 16;                 // clipmap levels, each twice the texel of the one before
    // A level finer than a texel per screen pixel, as Unreal renders its sun at Epic quality (1.5
    // finer): on the city's street camera 0.35 x the misclassified pixels of 4 stabilised
    // cascades, against 0.74 x at 0 (`report --scene city --sweep virtual`).
    int virtualLodBias = 1;                 // levels finer than a texel per screen pixel
    ShadowCachePolicy cache = ShadowCachePolicy::Off;
    int cacheInterval = 4;                  // every-n: frames of moving casters between redraws
    // Every view (or page) drawn every frame, as a moving light draws them: any cache's worst
    // case, as Unreal's r.Shadow.Virtual.Cache.ForceInvalidateDirectional emulates a moving sun.
    bool forceInvalidate = false;

    bool operator==(const ShadowSettings&) const = default;
};

struct ShadingSettings {
    ShadingModel model = ShadingModel::BlinnPhong;
    // Colours the lit scene by how many screen pixels one shadow-map texel covers (aliasing at a
    // glance); the shadow term and every measurement stay as they are.
    bool texelDensity = false;
    bool shadowOnly = false;                // a view only: the shadow term alone, never in what is measured

    bool operator==(const ShadingSettings&) const = default;
};

struct CameraSettings {
    glm::dvec3 position{0.0, 0.0, 3.0};     // world units, finite, != target
    glm::dvec3 target{0.0, 0.0, 0.0};
    double fov = 45.0;                      // vertical full angle in degrees

    bool operator==(const CameraSettings&) const = default;
};

// The ray-traced reference the accuracy measurement compares against; nothing here changes
// what the renderer draws.
struct ReferenceSettings {
    double lightRadius = 0.25;              // disk light radius for the area reference, world units

    bool operator==(const ReferenceSettings&) const = default;
};

// Objects of the scene switched off as casters or receivers, by name, or "#i" for the object at
// index i (a name that is empty, shared or holds a comma): how much of a shadow one object
// casts, or whether a surface needs to receive at all, seen by switching it.
struct ObjectSwitches {
    QStringList noCast;                     // cast no shadow (not in the map, nor to the reference's rays)
    QStringList noReceive;                  // always lit, and out of what is measured

    bool operator==(const ObjectSwitches&) const = default;
};

// The latest scene.time there is, in seconds.
inline constexpr double kMaxSceneTime = 1e6;

// The scene's clock: where its moving objects are. A frame is a pure function of its settings,
// time included; a still scene ignores it.
struct AnimationSettings {
    double time = 0.0;                      // seconds since the scene's start
    bool play = false;                      // the window's clock runs (time advances with the wall clock)
    double speed = 1.0;                     // scene seconds per wall second while playing

    bool operator==(const AnimationSettings&) const = default;
};

// How frames are drawn, never what they show.
struct RasteriserSettings {
    RasteriserProfile profile = RasteriserProfile::Auto;

    bool operator==(const RasteriserSettings&) const = default;
};

struct Settings {
    QString scene = QStringLiteral("seed"); // one of sceneNames() (SceneNames.h), or a model or scene file's absolute path
    ObjectSwitches objects;                 // of `scene`
    AnimationSettings animation;
    LightSettings light;
    MapSettings map;
    BiasSettings bias;
    FilterSettings filter;
    MomentSettings moments;
    ShadowSettings shadow;
    ContactSettings contact;
    ShadingSettings shading;
    CameraSettings camera;
    ReferenceSettings reference;
    RasteriserSettings rasteriser;

    bool operator==(const Settings&) const = default;
};

struct SettingsIssue {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    QString key;        // dotted key, e.g. "light.near"
    QString message;    // what is wrong and how to fix it
};

// Every problem with a whole set of settings (errors first); empty when all is well.
// Per-field ranges are checked here too, so a struct filled in by code is held to the same
// rules as one parsed from text.
std::vector<SettingsIssue> validate(const Settings& settings);

// The first error of validate(), as an exception; warnings do not throw.
void ensureValid(const Settings& settings);

} // namespace shadowlab
