#include "ShadowTechnique.h"

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
                  {QStringLiteral("pcf 7x7"), {QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=7")}}}});
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
