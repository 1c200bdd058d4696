#include "ShadowTechnique.h"

#include "MomentMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

namespace shadowlab {

namespace {

QStringList noDefines(const Settings&) { return {}; }
std::vector<TechniqueUniform> noUniforms(const Settings&) { return {}; }

std::function<QString(const FilterSettings&)> plainLabel(const char* key)
{
    return [k = QString::fromLatin1(key)](const FilterSettings&) { return k; };
}

// What every moment technique's GLSL reads: the moments format decides the variant (16-bit
// quantisation), the rest are uniforms, so tuning them needs neither a new variant nor a new
// moments pass.
QStringList momentDefines(const Settings& s)
{
    return s.moments.format == MomentFormat::Rgba16F ? QStringList{QStringLiteral("MOMENTS_16BIT")} : QStringList{};
}

std::vector<TechniqueUniform> momentUniforms(const Settings& s)
{
    const MomentWarp warp = momentWarp(s);
    return {{"uBleeding", float(s.filter.bleeding)},
            {"uMomentBias", float(s.filter.momentBias)},
            {"uExponentPositive", float(warp.positive)},
            {"uExponentNegative", float(warp.negative)}};
}

TechniqueVariation momentVariation(const QString& label, const QString& key, QStringList more = {})
{
    return {label, QStringList{QStringLiteral("filter.mode=") + key} + more};
}

// Filterable maps: a moments pass stores a few powers (or exponential warps) of depth, a
// blur and mips prefilter them, and the lit pass reconstructs how much of the filtered
// footprint lies behind the receiver from a single filtered lookup.
void addMomentTechniques(std::vector<ShadowTechnique>& t)
{
    const QString bleeding = QStringLiteral("filter.bleeding"), bias = QStringLiteral("filter.moment_bias");
    const QString positive = QStringLiteral("filter.exponent_positive"), negative = QStringLiteral("filter.exponent_negative");
    t.push_back({FilterMode::Vsm, QStringLiteral("vsm"), QStringLiteral("VSM (2 moments)"),
                 QStringLiteral("vsm (2 moments, 1 filtered tap): variance shadow maps; blurred and mipmapped like a texture, "
                                "but light bleeds where occluders overlap at different depths"),
                 QStringLiteral("shadow/vsm.glsl"), ShadowMapKind::Moments, {ShadowSampler::Moments}, {bleeding, bias},
                 momentDefines, momentUniforms, plainLabel("vsm"),
                 {momentVariation(QStringLiteral("vsm"), QStringLiteral("vsm")),
                  momentVariation(QStringLiteral("vsm 16-bit"), QStringLiteral("vsm"), {QStringLiteral("moments.format=16")})}});
    t.push_back({FilterMode::Evsm2, QStringLiteral("evsm2"), QStringLiteral("EVSM (2 moments)"),
                 QStringLiteral("evsm2 (2 moments of exp(c d), 1 filtered tap): exponential variance shadow maps; the warp "
                                "shrinks light bleeding, at the cost of exponents the format must hold"),
                 QStringLiteral("shadow/evsm2.glsl"), ShadowMapKind::Moments, {ShadowSampler::Moments}, {bleeding, bias, positive},
                 momentDefines, momentUniforms,
                 [](const FilterSettings& f) { return QStringLiteral("evsm2 c%1").arg(f.positiveExponent); },
                 {momentVariation(QStringLiteral("evsm2"), QStringLiteral("evsm2"))}});
    t.push_back({FilterMode::Evsm4, QStringLiteral("evsm4"), QStringLiteral("EVSM (4 moments)"),
                 QStringLiteral("evsm4 (4 moments of exp(c d) and -exp(-c d), 1 filtered tap): both warps, the least light "
                                "bleeding of the variance family; twice the memory of evsm2"),
                 QStringLiteral("shadow/evsm4.glsl"), ShadowMapKind::Moments, {ShadowSampler::Moments},
                 {bleeding, bias, positive, negative}, momentDefines, momentUniforms,
                 [](const FilterSettings& f) { return QStringLiteral("evsm4 c%1/%2").arg(f.positiveExponent).arg(f.negativeExponent); },
                 {momentVariation(QStringLiteral("evsm4"), QStringLiteral("evsm4")),
                  momentVariation(QStringLiteral("evsm4 16-bit"), QStringLiteral("evsm4"), {QStringLiteral("moments.format=16")})}});
    t.push_back({FilterMode::Msm, QStringLiteral("msm"), QStringLiteral("MSM (4 moments)"),
                 QStringLiteral("msm (4 moments, Hamburger, 1 filtered tap): moment shadow maps (Peters and Klein 2015); a sharper "
                                "bound than vsm's, 16-bit with their optimised quantisation"),
                 QStringLiteral("shadow/msm.glsl"), ShadowMapKind::Moments, {ShadowSampler::Moments}, {bleeding, bias},
                 momentDefines, momentUniforms, plainLabel("msm"),
                 {momentVariation(QStringLiteral("msm"), QStringLiteral("msm")),
                  momentVariation(QStringLiteral("msm 16-bit"), QStringLiteral("msm"), {QStringLiteral("moments.format=16")})}});
    t.push_back({FilterMode::Esm, QStringLiteral("esm"), QStringLiteral("ESM (1 moment)"),
                 QStringLiteral("esm (1 moment exp(c d), 1 filtered tap): exponential shadow maps; the cheapest filterable map, "
                                "but lit near contacts where receiver and occluder are closer than about 1/c of the depth range"),
                 QStringLiteral("shadow/esm.glsl"), ShadowMapKind::Moments, {ShadowSampler::Moments}, {positive},
                 momentDefines, momentUniforms,
                 [](const FilterSettings& f) { return QStringLiteral("esm c%1").arg(f.positiveExponent); },
                 {momentVariation(QStringLiteral("esm"), QStringLiteral("esm"))}});
}

std::vector<ShadowTechnique> makeTechniques()
{
    std::vector<ShadowTechnique> t;
    t.push_back({FilterMode::Hard, QStringLiteral("hard"), QStringLiteral("Hard"),
                 QStringLiteral("hard (1 tap): one comparison per pixel; aliased, blocky edges, the cheapest"),
                 QStringLiteral("shadow/hard.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareNearest}, {},
                 noDefines, noUniforms, plainLabel("hard"), {{QStringLiteral("hard"), {QStringLiteral("filter.mode=hard")}}}});
    t.push_back({FilterMode::Pcf, QStringLiteral("pcf"), QStringLiteral("PCF N×N"),
                 QStringLiteral("pcf (N x N taps): percentage-closer filtering over filter.kernel texels; softer edges at N² taps"),
                 QStringLiteral("shadow/pcf.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareNearest},
                 {QStringLiteral("filter.kernel")},
                 [](const Settings& s) { return QStringList{QStringLiteral("PCF_KERNEL %1").arg(s.filter.kernel)}; }, noUniforms,
                 [](const FilterSettings& f) { return QStringLiteral("pcf %1×%1").arg(f.kernel); },
                 {{QStringLiteral("pcf 1x1"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=1")}},
                  {QStringLiteral("pcf 3x3"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=3")}},
                  {QStringLiteral("pcf 5x5"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=5")}},
                  {QStringLiteral("pcf 7x7"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=7")}}},
                 true});
    t.push_back({FilterMode::PcfDither4, QStringLiteral("pcf-dither4"), QStringLiteral("PCF dithered 4"),
                 QStringLiteral("pcf-dither4 (4 dithered taps): a 4 x 4 footprint in 4 lookups, placed per 2 x 2 pixel block"),
                 QStringLiteral("shadow/pcf-dither4.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareNearest}, {},
                 noDefines, noUniforms, plainLabel("pcf-dither4"), {{QStringLiteral("pcf-dither4"), {QStringLiteral("filter.mode=pcf-dither4")}}}});
    t.push_back({FilterMode::Pcf64, QStringLiteral("pcf64"), QStringLiteral("PCF 8×8"),
                 QStringLiteral("pcf64 (8 x 8 taps): the smoothest and most expensive box"),
                 QStringLiteral("shadow/pcf64.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareNearest}, {},
                 noDefines, noUniforms, plainLabel("pcf64"), {{QStringLiteral("pcf64"), {QStringLiteral("filter.mode=pcf64")}}}});
    t.push_back({FilterMode::HwBilinear, QStringLiteral("hw-bilinear"), QStringLiteral("Hardware bilinear"),
                 QStringLiteral("hw-bilinear (hardware compare, bilinear): one tap that blends four comparisons; smooth edges for the cost of one"),
                 QStringLiteral("shadow/hw-bilinear.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareLinear}, {},
                 noDefines, noUniforms, plainLabel("hw-bilinear"), {{QStringLiteral("hw-bilinear"), {QStringLiteral("filter.mode=hw-bilinear")}}}});
    t.push_back({FilterMode::Poisson, QStringLiteral("poisson"), QStringLiteral("Poisson disk"),
                 QStringLiteral("poisson (filter.taps taps): a Poisson disk of filter.radius texels, rotated per pixel; round, "
                                "noise instead of banding, its bias grows with each tap's distance"),
                 QStringLiteral("shadow/poisson.glsl"), ShadowMapKind::DepthCompare, {ShadowSampler::CompareNearest},
                 {QStringLiteral("filter.taps"), QStringLiteral("filter.radius")},
                 [](const Settings& s) { return QStringList{QStringLiteral("POISSON_TAPS %1").arg(s.filter.taps)}; },
                 [](const Settings& s) { return std::vector<TechniqueUniform>{{"uPoissonRadius", float(s.filter.radius)}}; },
                 [](const FilterSettings& f) { return QStringLiteral("poisson %1 r%2").arg(f.taps).arg(f.radius); },
                 {{QStringLiteral("poisson 16 r2.5"), {QStringLiteral("filter.mode=poisson"), QStringLiteral("filter.taps=16"),
                                                       QStringLiteral("filter.radius=2.5")}},
                  {QStringLiteral("poisson 32 r5"), {QStringLiteral("filter.mode=poisson"), QStringLiteral("filter.taps=32"),
                                                     QStringLiteral("filter.radius=5")}}},
                 true});
    t.push_back({FilterMode::Pcss, QStringLiteral("pcss"), QStringLiteral("PCSS (soft)"),
                 QStringLiteral("pcss (16 + filter.taps taps): percentage-closer soft shadows of a disk light of light.radius; "
                                "a blocker search, then a Poisson filter as wide as the penumbra there"),
                 QStringLiteral("shadow/pcss.glsl"), ShadowMapKind::RawDepth, {ShadowSampler::CompareNearest, ShadowSampler::RawNearest},
                 {QStringLiteral("filter.taps")},
                 [](const Settings& s) { return QStringList{QStringLiteral("POISSON_TAPS %1").arg(s.filter.taps)}; },
                 [](const Settings& s) {
                     // A directional light has the angular size the disk has seen from the target,
                     // as the area reference traces it (accuracy/ShadowReference.cpp).
                     double size = s.reference.lightRadius;
                     if (s.light.projection == LightProjection::Ortho)
                         size /= std::max(glm::length(s.light.position - s.light.target), 1e-12);
                     return std::vector<TechniqueUniform>{{"uLightSize", float(size)}};
                 },
                 [](const FilterSettings& f) { return QStringLiteral("pcss %1").arg(f.taps); },
                 {{QStringLiteral("pcss 16"), {QStringLiteral("filter.mode=pcss"), QStringLiteral("filter.taps=16")}},
                  {QStringLiteral("pcss 32"), {QStringLiteral("filter.mode=pcss"), QStringLiteral("filter.taps=32")}}},
                 true});
    addMomentTechniques(t);
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
         QStringLiteral("PCF kernel width in texels (pcf mode): wider softens edges and hides aliasing at N^2 taps per pixel"),
         1, 9, true, &FilterSettings::kernel},
        {QStringLiteral("filter.taps"), QStringLiteral("Poisson taps"), QString(),
         QStringLiteral("Taps of the Poisson disk (poisson, and pcss's filter after its 16-tap blocker search): more taps, less noise, "
                        "linearly more time"),
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

QString filterLabel(const FilterSettings& filter)
{
    return shadowTechnique(filter.mode).describe(filter);
}

bool usesParameter(const FilterSettings& filter, const QString& parameterKey)
{
    return shadowTechnique(filter.mode).parameters.contains(parameterKey);
}

} // namespace shadowlab
