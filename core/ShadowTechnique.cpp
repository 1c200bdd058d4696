#include "ShadowTechnique.h"

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
    t.push_back({FilterMode::Pcf64, QStringLiteral("pcf64"), QStringLiteral("PCF 64"),
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
    t.push_back({FilterMode::Pcss, QStringLiteral("pcss"), QStringLiteral("PCSS"),
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
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (int(t[i].mode) != int(i))
            throw std::logic_error("the technique table must list techniques in FilterMode order");
    }
    return t;
}

} // namespace

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
