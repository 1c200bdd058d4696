#include "ShadowTechnique.h"

#include "MomentMath.h"
#include "ShaderConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

namespace shadowlab {

namespace {

QStringList noDefines(const Settings&) { return {}; }
TechniqueShaderValues noShaderValues(const Settings&) { return {}; }

std::function<QString(const FilterSettings&)> plainLabel(const char* key)
{
    return [k = QString::fromLatin1(key)](const FilterSettings&) { return k; };
}

// What every moment technique's GLSL reads: the moments format decides the variant (16-bit
// quantisation), the rest are parameters (and the warp's exponents, momentWarp, which the moments
// pass reads too), so tuning them needs neither a new variant nor a new moments pass.
QStringList momentDefines(const Settings& s)
{
    return s.moments.format == MomentFormat::Rgba16F ? QStringList{QStringLiteral("MOMENTS_16BIT")} : QStringList{};
}

TechniqueShaderValues momentShaderValues(const Settings& s)
{
    return {.bleeding = float(s.filter.bleeding), .momentBias = float(s.filter.momentBias)};
}

// The disk light's size for the blocker searches (pcss, dpcf): a directional light has the
// angular size the disk has seen from the target, as the area reference traces it
// (accuracy/ShadowReference.cpp).
TechniqueShaderValues lightSizeShaderValue(const Settings& s)
{
    double size = s.reference.lightRadius;
    if (s.light.projection == LightProjection::Ortho)
        size /= std::max(glm::length(s.light.position - s.light.target), 1e-12);
    return {.lightSize = float(size)};
}

TechniqueVariation momentVariation(const QString& label, const QString& key, QStringList more = {})
{
    return {label, QStringList{QStringLiteral("filter.mode=") + key} + more};
}

// Filterable maps: a moments pass stores a few powers (or exponential warps) of depth, a
// blur and mips prefilter them, and the lit pass reconstructs how much of the filtered
// footprint lies behind the receiver from a single filtered lookup. First the variance family:
// two or four moments, plain or exponentially warped.
void addVarianceTechniques(std::vector<ShadowTechnique>& t)
{
    const QString bleeding = QStringLiteral("filter.bleeding"), bias = QStringLiteral("filter.moment_bias");
    const QString positive = QStringLiteral("filter.exponent_positive"), negative = QStringLiteral("filter.exponent_negative");
    t.push_back({
        .mode = FilterMode::Vsm,
        .key = QStringLiteral("vsm"),
        .label = QStringLiteral("VSM (2 moments)"),
        .help = QStringLiteral("vsm (2 moments, 1 filtered tap): variance shadow maps; blurred and mipmapped like a texture, "
            "but light bleeds where occluders overlap at different depths"),
        .shaderFile = QStringLiteral("shadow/vsm.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 3,
        .coverage = true,
        .parameters = {bleeding, bias},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = plainLabel("vsm"),
        .sweep = {momentVariation(QStringLiteral("vsm"), QStringLiteral("vsm")),
            momentVariation(QStringLiteral("vsm 16-bit"), QStringLiteral("vsm"), {QStringLiteral("moments.format=16")})},
    });
    t.push_back({
        .mode = FilterMode::Evsm2,
        .key = QStringLiteral("evsm2"),
        .label = QStringLiteral("EVSM (2 moments)"),
        .help = QStringLiteral("evsm2 (2 moments of exp(c d), 1 filtered tap): exponential variance shadow maps; the warp "
            "shrinks light bleeding, at the cost of exponents the format must hold"),
        .shaderFile = QStringLiteral("shadow/evsm2.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 3,
        .coverage = true,
        .parameters = {bleeding, bias, positive},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = [](const FilterSettings& f) { return QStringLiteral("evsm2 c%1").arg(f.positiveExponent); },
        .sweep = {momentVariation(QStringLiteral("evsm2"), QStringLiteral("evsm2"))},
    });
    t.push_back({
        .mode = FilterMode::Evsm4,
        .key = QStringLiteral("evsm4"),
        .label = QStringLiteral("EVSM (4 moments)"),
        .help = QStringLiteral("evsm4 (4 moments of exp(c d) and -exp(-c d), 1 filtered tap): both warps, the least light "
            "bleeding of the variance family; twice the memory of evsm2"),
        .shaderFile = QStringLiteral("shadow/evsm4.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 4,
        .parameters = {bleeding, bias, positive, negative},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = [](const FilterSettings& f) { return QStringLiteral("evsm4 c%1/%2").arg(f.positiveExponent).arg(f.negativeExponent); },
        .sweep = {momentVariation(QStringLiteral("evsm4"), QStringLiteral("evsm4")),
            momentVariation(QStringLiteral("evsm4 16-bit"), QStringLiteral("evsm4"), {QStringLiteral("moments.format=16")})},
    });
}

// Four power moments (Hamburger or Hausdorff), and one exponential.
void addMomentAndExponentialTechniques(std::vector<ShadowTechnique>& t)
{
    const QString bleeding = QStringLiteral("filter.bleeding"), bias = QStringLiteral("filter.moment_bias");
    const QString positive = QStringLiteral("filter.exponent_positive");
    t.push_back({
        .mode = FilterMode::Msm,
        .key = QStringLiteral("msm"),
        .label = QStringLiteral("MSM (4 moments)"),
        .help = QStringLiteral("msm (4 moments, Hamburger, 1 filtered tap): moment shadow maps (Peters and Klein 2015); a sharper "
            "bound than vsm's, 16-bit with their optimised quantisation"),
        .shaderFile = QStringLiteral("shadow/msm.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 4,
        .parameters = {bleeding, bias},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = plainLabel("msm"),
        .sweep = {momentVariation(QStringLiteral("msm"), QStringLiteral("msm")),
            momentVariation(QStringLiteral("msm 16-bit"), QStringLiteral("msm"), {QStringLiteral("moments.format=16")})},
        .litToItsBias = true,
    });
    t.push_back({
        .mode = FilterMode::MsmHausdorff,
        .key = QStringLiteral("msm-hausdorff"),
        .label = QStringLiteral("MSM Hausdorff (4 moments)"),
        .help = QStringLiteral("msm-hausdorff (4 moments, Hausdorff, 1 filtered tap): msm's moments with every depth known to lie "
            "in the light's volume; less bleeding where occluders overlap near its ends, a few more operations"),
        .shaderFile = QStringLiteral("shadow/msm-hausdorff.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 4,
        .parameters = {bleeding, bias},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = plainLabel("msm-hausdorff"),
        .sweep = {momentVariation(QStringLiteral("msm-hausdorff"), QStringLiteral("msm-hausdorff")),
            momentVariation(QStringLiteral("msm-hausdorff 16-bit"), QStringLiteral("msm-hausdorff"), {QStringLiteral("moments.format=16")})},
        .litToItsBias = true,
        .farPlaneReadsLit = false,
    });
    t.push_back({
        .mode = FilterMode::Esm,
        .key = QStringLiteral("esm"),
        .label = QStringLiteral("ESM (1 moment)"),
        .help = QStringLiteral("esm (1 moment exp(c d), 1 filtered tap): exponential shadow maps; the cheapest filterable map, "
            "but lit near contacts where receiver and occluder are closer than about 1/c of the depth range"),
        .shaderFile = QStringLiteral("shadow/esm.glsl"),
        .map = ShadowMapKind::Moments,
        .samplers = {ShadowSampler::Moments},
        .momentChannels = 2,
        .coverage = true,
        .parameters = {positive},
        .defines = momentDefines,
        .shaderValues = momentShaderValues,
        .describe = [](const FilterSettings& f) { return QStringLiteral("esm c%1").arg(f.positiveExponent); },
        .sweep = {momentVariation(QStringLiteral("esm"), QStringLiteral("esm"))},
    });
}

// One compare per tap on a depth map: a single tap, and boxes of filter.kernel texels.
void addHardAndBoxTechniques(std::vector<ShadowTechnique>& t)
{
    t.push_back({
        .mode = FilterMode::Hard,
        .key = QStringLiteral("hard"),
        .label = QStringLiteral("Hard"),
        .help = QStringLiteral("hard (1 tap): one comparison per pixel; aliased, blocky edges, the cheapest"),
        .shaderFile = QStringLiteral("shadow/hard.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareNearest},
        .parameters = {},
        .defines = noDefines,
        .shaderValues = noShaderValues,
        .describe = plainLabel("hard"),
        .sweep = {{QStringLiteral("hard"), {QStringLiteral("filter.mode=hard")}}},
        .tapReach = [](const FilterSettings&) -> std::optional<double> { return 0.0; },
        .referencesStayNearer = [](const Settings&) { return true; },
    });
    t.push_back({
        .mode = FilterMode::Pcf,
        .key = QStringLiteral("pcf"),
        .label = QStringLiteral("PCF N×N"),
        .help = QStringLiteral("pcf (N×N taps): percentage-closer filtering over filter.kernel texels; softer edges at N² taps"),
        .shaderFile = QStringLiteral("shadow/pcf.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareNearest},
        .parameters = {QStringLiteral("filter.kernel")},
        .defines = [](const Settings& s) { return QStringList{QStringLiteral("PCF_KERNEL %1").arg(s.filter.kernel)}; },
        .shaderValues = noShaderValues,
        .describe = [](const FilterSettings& f) { return QStringLiteral("pcf %1×%1").arg(f.kernel); },
        .sweep = {{QStringLiteral("pcf 1x1"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=1")}},
            {QStringLiteral("pcf 3x3"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=3")}},
            {QStringLiteral("pcf 5x5"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=5")}},
            {QStringLiteral("pcf 7x7"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=7")}}},
        .penumbraOnly = true,
        .tapReach = [](const FilterSettings& f) -> std::optional<double> { return double((f.kernel - 1) / 2); },
        .taps = [](const FilterSettings& f) { return f.kernel * f.kernel; },
        .referencesStayNearer = [](const Settings& s) { return !s.bias.receiverPlane; },
    });
    t.push_back({
        .mode = FilterMode::PcfOptimized,
        .key = QStringLiteral("pcf-optimized"),
        .label = QStringLiteral("PCF optimized (bilinear taps)"),
        .help = QStringLiteral("pcf-optimized (4, 9 or 16 bilinear taps): a smooth filter.kernel-wide kernel (3, 5 or 7 texels) from "
            "weighted hardware-bilinear compares, as in The Witness; softer than pcf's box at about a third of its lookups"),
        .shaderFile = QStringLiteral("shadow/pcf-optimized.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareLinear},
        .parameters = {QStringLiteral("filter.kernel")},
        .defines = [](const Settings& s) { return QStringList{QStringLiteral("PCF_KERNEL %1").arg(optimizedPcfKernel(s.filter))}; },
        .shaderValues = noShaderValues,
        .describe = [](const FilterSettings& f) { return QStringLiteral("pcf-optimized %1×%1").arg(optimizedPcfKernel(f)); },
        .sweep = {{QStringLiteral("pcf-optimized 3x3"), {QStringLiteral("filter.mode=pcf-optimized"), QStringLiteral("filter.kernel=3")}},
            {QStringLiteral("pcf-optimized 5x5"), {QStringLiteral("filter.mode=pcf-optimized"), QStringLiteral("filter.kernel=5")}},
            {QStringLiteral("pcf-optimized 7x7"), {QStringLiteral("filter.mode=pcf-optimized"), QStringLiteral("filter.kernel=7")}}},
        .penumbraOnly = true,
        // Each bilinear tap reads the 2 x 2 texels around it (tapReachTexels adds that).
        .tapReach = [](const FilterSettings& f) -> std::optional<double> { return double(optimizedPcfKernel(f) - 1) / 2.0 + 0.5; },
        .taps = [](const FilterSettings& f) { return (optimizedPcfKernel(f) + 1) / 2 * ((optimizedPcfKernel(f) + 1) / 2); },
        .referencesStayNearer = [](const Settings& s) { return !s.bias.receiverPlane; },
    });
}

// Kernels of a fixed size: dithered, 8×8, and the hardware's bilinear compare.
void addFixedKernelTechniques(std::vector<ShadowTechnique>& t)
{
    t.push_back({
        .mode = FilterMode::PcfDither4,
        .key = QStringLiteral("pcf-dither4"),
        .label = QStringLiteral("PCF dithered 4"),
        .help = QStringLiteral("pcf-dither4 (4 dithered taps): a 4×4 footprint in 4 lookups, placed per 2×2 pixel block"),
        .shaderFile = QStringLiteral("shadow/pcf-dither4.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareNearest},
        .parameters = {},
        .defines = noDefines,
        .shaderValues = noShaderValues,
        .describe = plainLabel("pcf-dither4"),
        .sweep = {{QStringLiteral("pcf-dither4"), {QStringLiteral("filter.mode=pcf-dither4")}}},
        .tapReach = [](const FilterSettings&) -> std::optional<double> { return 2.5; },
        .taps = [](const FilterSettings&) { return 4; },
        .referencesStayNearer = [](const Settings& s) { return !s.bias.receiverPlane; },
    });
    t.push_back({
        .mode = FilterMode::Pcf64,
        .key = QStringLiteral("pcf64"),
        .label = QStringLiteral("PCF 8×8"),
        .help = QStringLiteral("pcf64 (8×8 taps): the smoothest and most expensive box"),
        .shaderFile = QStringLiteral("shadow/pcf64.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareNearest},
        .parameters = {},
        .defines = noDefines,
        .shaderValues = noShaderValues,
        .describe = plainLabel("pcf64"),
        .sweep = {{QStringLiteral("pcf64"), {QStringLiteral("filter.mode=pcf64")}}},
        .tapReach = [](const FilterSettings&) -> std::optional<double> { return kPcf64TapReach; },
        .taps = [](const FilterSettings&) { return kPcf64Side * kPcf64Side; },
        .referencesStayNearer = [](const Settings& s) { return !s.bias.receiverPlane; },
    });
    t.push_back({
        .mode = FilterMode::HwBilinear,
        .key = QStringLiteral("hw-bilinear"),
        .label = QStringLiteral("Hardware bilinear"),
        .help = QStringLiteral("hw-bilinear (hardware compare, bilinear): one tap that blends four comparisons; smooth edges for the cost of one"),
        .shaderFile = QStringLiteral("shadow/hw-bilinear.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareLinear},
        .parameters = {},
        .defines = noDefines,
        .shaderValues = noShaderValues,
        .describe = plainLabel("hw-bilinear"),
        .sweep = {{QStringLiteral("hw-bilinear"), {QStringLiteral("filter.mode=hw-bilinear")}}},
        .tapReach = [](const FilterSettings&) -> std::optional<double> { return 0.0; },
        .referencesStayNearer = [](const Settings&) { return true; },
    });
}

// Disks of taps: a fixed radius, and a penumbra estimated from a blocker search.
void addDiskTechniques(std::vector<ShadowTechnique>& t)
{
    t.push_back({
        .mode = FilterMode::Poisson,
        .key = QStringLiteral("poisson"),
        .label = QStringLiteral("Poisson disk"),
        .help = QStringLiteral("poisson (filter.taps taps): a Poisson disk of filter.radius texels, rotated per pixel; round, "
            "noise instead of banding, its bias grows with each tap's distance"),
        .shaderFile = QStringLiteral("shadow/poisson.glsl"),
        .map = ShadowMapKind::DepthCompare,
        .samplers = {ShadowSampler::CompareNearest},
        .parameters = {QStringLiteral("filter.taps"), QStringLiteral("filter.radius")},
        .defines = [](const Settings& s) { return QStringList{QStringLiteral("POISSON_TAPS %1").arg(s.filter.taps)}; },
        .shaderValues = [](const Settings& s) { return TechniqueShaderValues{.poissonRadius = float(s.filter.radius)}; },
        .describe = [](const FilterSettings& f) { return QStringLiteral("poisson %1 r%2").arg(f.taps).arg(f.radius); },
        .sweep = {{QStringLiteral("poisson 16 r2.5"), {QStringLiteral("filter.mode=poisson"), QStringLiteral("filter.taps=16"),
            QStringLiteral("filter.radius=2.5")}},
            {QStringLiteral("poisson 32 r5"), {QStringLiteral("filter.mode=poisson"), QStringLiteral("filter.taps=32"),
            QStringLiteral("filter.radius=5")}}},
        .penumbraOnly = true,
        .tapReach = [](const FilterSettings& f) -> std::optional<double> { return f.radius; },
        .taps = [](const FilterSettings& f) { return f.taps; },
    });
    t.push_back({
        .mode = FilterMode::Pcss,
        .key = QStringLiteral("pcss"),
        .label = QStringLiteral("PCSS (soft)"),
        .help = QStringLiteral("pcss (16 + filter.taps taps): percentage-closer soft shadows of a disk light of light.radius; "
            "a blocker search, then a Poisson filter as wide as the penumbra there"),
        .shaderFile = QStringLiteral("shadow/pcss.glsl"),
        .map = ShadowMapKind::RawDepth,
        .samplers = {ShadowSampler::CompareNearest, ShadowSampler::RawNearest},
        .parameters = {QStringLiteral("filter.taps")},
        .defines = [](const Settings& s) { return QStringList{QStringLiteral("POISSON_TAPS %1").arg(s.filter.taps)}; },
        .shaderValues = lightSizeShaderValue,
        .describe = [](const FilterSettings& f) { return QStringLiteral("pcss %1").arg(f.taps); },
        .sweep = {{QStringLiteral("pcss 16"), {QStringLiteral("filter.mode=pcss"), QStringLiteral("filter.taps=16")}},
            {QStringLiteral("pcss 32"), {QStringLiteral("filter.mode=pcss"), QStringLiteral("filter.taps=32")}}},
        .penumbraOnly = true,
        .searchesBlockers = true,
        .taps = [](const FilterSettings& f) { return kPcssBlockerTaps + f.taps; },
    });
    t.push_back({
        .mode = FilterMode::Dpcf,
        .key = QStringLiteral("dpcf"),
        .label = QStringLiteral("DPCF (contact hardening)"),
        .help = QStringLiteral("dpcf (filter.taps taps): PCF with contact hardening, as in Filament; pcss's blocker search is also "
            "the filter, sharpened where blockers are near; half of pcss's lookups, penumbra width approximated"),
        .shaderFile = QStringLiteral("shadow/dpcf.glsl"),
        .map = ShadowMapKind::RawDepth,
        .samplers = {ShadowSampler::CompareNearest, ShadowSampler::RawNearest},
        .parameters = {QStringLiteral("filter.taps")},
        .defines = [](const Settings& s) { return QStringList{QStringLiteral("POISSON_TAPS %1").arg(s.filter.taps)}; },
        .shaderValues = lightSizeShaderValue,
        .describe = [](const FilterSettings& f) { return QStringLiteral("dpcf %1").arg(f.taps); },
        .sweep = {{QStringLiteral("dpcf 16"), {QStringLiteral("filter.mode=dpcf"), QStringLiteral("filter.taps=16")}},
            {QStringLiteral("dpcf 32"), {QStringLiteral("filter.mode=dpcf"), QStringLiteral("filter.taps=32")}}},
        .penumbraOnly = true,
        .searchesBlockers = true,
        .taps = [](const FilterSettings& f) { return f.taps; },
    });
}

std::vector<ShadowTechnique> makeTechniques()
{
    std::vector<ShadowTechnique> t;
    addHardAndBoxTechniques(t);
    addFixedKernelTechniques(t);
    addDiskTechniques(t);
    addVarianceTechniques(t);
    addMomentAndExponentialTechniques(t);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (int(t[i].mode) != int(i))
            throw std::logic_error("the technique table must list techniques in FilterMode order");
    }
    return t;
}

} // namespace

const ShadowStorageLimits& shadowStorageLimits(ShadowMapKind map)
{
    static const ShadowStorageLimits depth{.map = ShadowMapKind::DepthCompare, .refusedWithViews = {}, .reason = {}};
    // The mips of a map of several views would blend a view with its neighbours at every
    // level where a texel's filter reaches across a tile's edge.
    static const ShadowStorageLimits moments{
        .map = ShadowMapKind::Moments,
        .refusedWithViews = QStringLiteral("moments.mipmaps"),
        .reason = QStringLiteral("the mip levels of a map holding several views (cascades or a point light's faces) would blend "
                                 "neighbouring views; set moments.mipmaps=false, or shadow.cascades=1 with a directional or spot light")};
    return map == ShadowMapKind::Moments ? moments : depth;
}

const std::vector<ShadowTechnique>& shadowTechniques()
{
    static const std::vector<ShadowTechnique> table = makeTechniques();
    return table;
}

const ShadowTechnique& shadowTechnique(FilterMode mode)
{
    return shadowTechniques().at(std::size_t(mode));
}

const std::vector<TechniqueParameter>& techniqueParameters()
{
    static const std::vector<TechniqueParameter> parameters{
        {QStringLiteral("filter.kernel"), QStringLiteral("PCF kernel"), QStringLiteral(" texels"),
         QStringLiteral("PCF kernel width in texels (pcf; pcf-optimized has 3, 5 and 7): wider softens edges and hides aliasing, at N² taps "
                        "per pixel for pcf, ((N + 1) / 2)² bilinear ones for pcf-optimized"),
         1, 9, true, &FilterSettings::kernel},
        {QStringLiteral("filter.taps"), QStringLiteral("Poisson taps"), QString(),
         QStringLiteral("Taps of the Poisson disk (poisson, pcss's filter after its 16-tap blocker search, dpcf's one pass): more taps, "
                        "less noise, linearly more time"),
         8, 64, false, &FilterSettings::taps},
        {QStringLiteral("filter.radius"), QStringLiteral("Poisson radius"), QStringLiteral(" texels"),
         QStringLiteral("Radius of the Poisson disk in shadow-map texels (poisson mode): wider is softer at the same cost, "
                        "with sparser taps (noise) and more bias grown for the outer taps"),
         0.5, 32, false, &FilterSettings::radius},
        {QStringLiteral("filter.bleeding"), QStringLiteral("Bleeding reduction"), QString(),
         QStringLiteral("Light-bleeding reduction (vsm, evsm, msm): visibility below this reads as full shadow and the rest is "
                        "stretched over [0, 1]; removes the false light where occluders overlap, at the cost of darker, "
                        "narrower penumbrae"),
         0, 0.95, false, &FilterSettings::bleeding},
        {QStringLiteral("filter.moment_bias"), QStringLiteral("Moment bias"), QString(),
         QStringLiteral("Moment bias (vsm, evsm, msm): the least variance (vsm: in squared [0, 1] depth; evsm: relative to the "
                        "squared warped depth) or the weight that blends the moments toward a flat distribution (msm); too "
                        "little shows acne and noise where the format runs out of precision (16-bit needs about 1e-4), too "
                        "much lightens shadows near their casters"),
         0, 0.01, false, &FilterSettings::momentBias, 6},
        {QStringLiteral("filter.exponent_positive"), QStringLiteral("Positive exponent"), QString(),
         QStringLiteral("Exponent c of the warp exp(c d) (esm, evsm2, evsm4): larger cuts light bleeding and sharpens contacts, "
                        "but must fit the format: used as at most 5.54 (evsm) or 11.08 (esm) with moments.format=16, "
                        "44.3 or 88.7 with 32"),
         0, 80, false, &FilterSettings::positiveExponent},
        {QStringLiteral("filter.exponent_negative"), QStringLiteral("Negative exponent"), QString(),
         QStringLiteral("Exponent of evsm4's second warp -exp(-c d): fixes bleeding the positive warp leaves on near receivers; "
                        "clamped like filter.exponent_positive (5.54 at 16-bit)"),
         0, 80, false, &FilterSettings::negativeExponent},
    };
    return parameters;
}

int optimizedPcfKernel(const FilterSettings& filter)
{
    return std::clamp(filter.kernel | 1, 3, 7);
}

QString filterLabel(const FilterSettings& filter)
{
    return shadowTechnique(filter.mode).describe(filter);
}

bool usesParameter(const FilterSettings& filter, const QString& parameterKey)
{
    return shadowTechnique(filter.mode).parameters.contains(parameterKey);
}

} // namespace shadowlab
