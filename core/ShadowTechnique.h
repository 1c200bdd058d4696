#pragma once

#include "Settings.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <variant>
#include <vector>

namespace shadowlab {

// What a technique reads from the shadow pass.
enum class ShadowMapKind {
    DepthCompare,   // a depth texture, compared in hardware against the receiver's depth
    RawDepth,       // the same depth texture read as numbers (a blocker search, say)
    Moments,        // a filterable moments texture (VSM, EVSM)
};

// One sampler a technique's GLSL declares, bound to its own texture unit. Compare samplers
// are `uniform sampler2DShadow uShadowMap`, raw ones `uniform sampler2D uShadowDepth`.
enum class ShadowSampler {
    CompareNearest, // one comparison per tap
    CompareLinear,  // a hardware bilinear blend of four comparisons per tap
    RawNearest,     // depth values, no comparison
    Moments,        // the moments map, filtered (`uniform sampler2D uShadowMoments`): bilinear,
                    // trilinear with moments.mipmaps, anisotropic with moments.anisotropy
};

// A setting only some techniques read (a kernel width, a radius, a tap count). Its key joins
// the settings table right after `filter.mode`, with this range; the properties dock enables
// its row only while a technique that lists it is selected.
struct TechniqueParameter {
    QString key;            // "filter.kernel"
    QString label;          // the dock row's label
    QString unit;           // shown after the range in the dock, e.g. " texels"
    QString help;           // one line: what it does and what it trades against
    double minimum = 0.0;
    double maximum = 0.0;
    bool oddOnly = false;   // integers only
    std::variant<int FilterSettings::*, double FilterSettings::*> field;   // where the value lives
    int decimals = 2;       // the dock's precision for a number
};

// What a technique's GLSL reads at run time, for the current settings (a radius, a light size):
// set every frame in the lit pass's frame block (renderer/UniformBlocks.h), so changing one
// needs no new shader variant. A technique leaves what it does not read at 0.
struct TechniqueShaderValues {
    float bleeding = 0.0f;      // moments: filter.bleeding
    float momentBias = 0.0f;    // moments: filter.moment_bias
    float lightSize = 0.0f;     // blocker searches (pcss, dpcf): the disk light's size
    float poissonRadius = 0.0f; // poisson: filter.radius, in texels
};

// One configuration a sweep tries for a technique: its label and the settings it changes.
struct TechniqueVariation {
    QString label;
    QStringList assignments;    // "key=value"
};

// A row of the technique table: everything the settings, the lit pass, the dock, the help
// page, the report's sweeps and the audit need to know about one shadow filter.
struct ShadowTechnique {
    FilterMode mode;
    QString key;                    // the `filter.mode` value
    QString label;                  // for people: dock, help page
    QString help;                   // one line: what it does, what it costs
    QString shaderFile;             // under shaders/: defines float filterShadow(vec2 uv, float reference)
    ShadowMapKind map = ShadowMapKind::DepthCompare;   // the renderer refuses kinds it does not build
    std::vector<ShadowSampler> samplers;    // in texture-unit order
    // Channels it stores (1 to 4), its coverage included: the moments map's (R, RG or RGBA; three
    // take RGBA, which GPUs render to), so that a technique of fewer writes, blurs and reads no
    // more. 0 for depth maps.
    int momentChannels = 0;
    // Whether its last channel is the share of the texel casters cover, its moments weighted by
    // it (shaders/moments_common.glsl): a receiver then needs no place in the map, so floors are
    // left out (bias.skip_floors) and the map is cleared to zeros. Only where a channel is free
    // after the moments: vsm, evsm2, esm.
    bool coverage = false;
    QStringList parameters;         // keys of techniqueParameters() it reads
    // Extra #defines of the lit pass's variant (compile-time parameters such as a kernel width).
    std::function<QStringList(const Settings&)> defines;
    // What its GLSL reads at run time; nothing for most.
    std::function<TechniqueShaderValues(const Settings&)> shaderValues;
    // The short name of a configuration, with its parameters ("pcf 3×3"); labels everywhere.
    std::function<QString(const FilterSettings&)> describe;
    std::vector<TechniqueVariation> sweep;  // what `report --sweep filters` and the dock try
    // Reads the min/max depth mip of the map to skip its taps where the whole footprint is lit
    // or shadowed (filter.early_out): the renderer builds the mip with each shadow pass then.
    bool penumbraOnly = false;
    // Searches the map for blockers over the region a disk light's blockers may lie in (pcss,
    // dpcf): it reads the same min/max depth mip to narrow that region to the nearest depth the
    // map holds there, so the renderer builds the mip with each shadow pass whatever
    // filter.early_out says (shaders/blocker_search.glsl).
    bool searchesBlockers = false;
    // How far its taps read around the receiver's own texel, in texels (the shadow reach,
    // core/ShadowReach.h), or nullopt where a lookup may read anywhere in the map: a blocker
    // search spans up to half of it. A moment technique's is its blur's radius, which
    // tapReachTexels gives it unless a coarse mip or an anisotropic footprint averages texels far
    // from the pixel.
    std::function<std::optional<double>(const FilterSettings&)> tapReach = [](const FilterSettings&) -> std::optional<double> {
        return std::nullopt;
    };
    // Texture reads of one lookup, at most (a bilinear or a hardware-compared read counts once;
    // an early-out where the footprint is uniform reads fewer): the same on any GPU, so the
    // cost it puts beside times (FrameCounts).
    std::function<int(const FilterSettings&)> taps = [](const FilterSettings&) { return 1; };
    // Whether every tap compares against the receiver's own depth (biased), never a depth grown
    // away from the light along the receiver's plane or with the tap's distance.
    std::function<bool(const Settings&)> referencesStayNearer = [](const Settings&) { return false; };
    // Whether a receiver whose footprint holds no caster reads lit only to within
    // filter.moment_bias: msm's bias blends the moments toward a distribution with that share
    // half at depth 0, in front of every receiver, and the bleeding reduction stretches it. The
    // software profile's reach skips such a receiver's lookup, shading it exactly lit, only
    // while the two differ by less than a step (core/ShadowReach.h's skippedLookupsReadTheSame).
    bool litToItsBias = false;
    // Whether a receiver whose footprint holds only the far plane's moments, behind it, reads
    // lit: msm-hausdorff's reconstruction, bounded to the light's volume, is ill-conditioned at
    // its far end and may shade a receiver near it (by up to 0.37 in cascades). Without it a
    // moments map keeps its floors everywhere and every receiver looks up (no shadow reach).
    bool farPlaneReadsLit = true;
};

// What a storage of the light's views (renderer/ShadowStorage.h draws them) cannot do with
// several views in one map, and why: validate() refuses it with this reason.
struct ShadowStorageLimits {
    ShadowMapKind map;
    QString refusedWithViews;       // a bool key that must stay false with several views; empty: none
    QString reason;
};
const ShadowStorageLimits& shadowStorageLimits(ShadowMapKind map);

// Every technique, in FilterMode order (the order of the `filter.mode` choices).
const std::vector<ShadowTechnique>& shadowTechniques();
const ShadowTechnique& shadowTechnique(FilterMode mode);
// The parameters techniques read, in settings-table order.
const std::vector<TechniqueParameter>& techniqueParameters();

// The kernel pcf-optimized filters with: filter.kernel within the 3, 5 and 7 it has weights for.
int optimizedPcfKernel(const FilterSettings& filter);

// The label of a filter configuration, e.g. "hard" or "pcf 3×3".
QString filterLabel(const FilterSettings& filter);
// Whether the selected technique reads `parameterKey`.
bool usesParameter(const FilterSettings& filter, const QString& parameterKey);

} // namespace shadowlab
