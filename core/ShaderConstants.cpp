#include "ShaderConstants.h"

#include "ShadowViews.h"
#include "VirtualPages.h"

#include <charconv>
#include <iterator>

namespace shadowlab {

namespace {

// The GLSL name is the C++ name, spelt once.
#define SHADOWLAB_SHADER_CONSTANT(name) ShaderConstant{#name, name}

const ShaderConstant kConstants[] = {
    SHADOWLAB_SHADER_CONSTANT(kVirtualPageTexels),
    SHADOWLAB_SHADER_CONSTANT(kVirtualPageBorder),
    SHADOWLAB_SHADER_CONSTANT(kVirtualSlotTexels),
    SHADOWLAB_SHADER_CONSTANT(kVirtualLevelPages),
    SHADOWLAB_SHADER_CONSTANT(kMaxVirtualLevels),
    SHADOWLAB_SHADER_CONSTANT(kMaxShadowViews),
    SHADOWLAB_SHADER_CONSTANT(kPcf64Side),
    SHADOWLAB_SHADER_CONSTANT(kPcf64TapReach),
    SHADOWLAB_SHADER_CONSTANT(kPcssBlockerTaps),
    SHADOWLAB_SHADER_CONSTANT(kMaxBlurWeights),
    SHADOWLAB_SHADER_CONSTANT(kMaxDepthRangeLevels),
    SHADOWLAB_SHADER_CONSTANT(kNoCasterDepth),
    SHADOWLAB_SHADER_CONSTANT(kOwnFacetCosine),
    ShaderConstant{"kViewTints", std::span<const Rgb>(kViewTints)},
    SHADOWLAB_SHADER_CONSTANT(kDensityBlue),
    SHADOWLAB_SHADER_CONSTANT(kDensityGreen),
    SHADOWLAB_SHADER_CONSTANT(kDensityYellow),
    SHADOWLAB_SHADER_CONSTANT(kDensityRed),
    SHADOWLAB_SHADER_CONSTANT(kOutsideMapColour),
};

#undef SHADOWLAB_SHADER_CONSTANT

// A value as a GLSL expression of its type.
QByteArray glsl(int value) { return QByteArray::number(value); }
QByteArray glsl(float value) { return glslFloat(value); }

QByteArray glsl(const Rgb& c)
{
    return "vec3(" + glslFloat(c[0]) + ", " + glslFloat(c[1]) + ", " + glslFloat(c[2]) + ')';
}

QByteArray glsl(std::span<const Rgb> colours)
{
    QByteArray list;
    for (const Rgb& c : colours)
        list += (list.isEmpty() ? "" : ", ") + glsl(c);
    return "vec3[" + QByteArray::number(qsizetype(colours.size())) + "](" + list + ')';
}

} // namespace

std::span<const ShaderConstant> shaderConstants()
{
    return kConstants;
}

QByteArray glslDefine(const ShaderConstant& constant)
{
    return "#define " + QByteArray(constant.name) + ' ' + std::visit([](const auto& value) { return glsl(value); }, constant.value);
}

QByteArray glslConstants()
{
    QByteArray text;
    for (const ShaderConstant& constant : kConstants)
        text += glslDefine(constant) + '\n';
    return text;
}

QByteArray glslFloat(float value)
{
    char digits[32];
    const std::to_chars_result end = std::to_chars(std::begin(digits), std::end(digits), value);
    QByteArray text(digits, int(end.ptr - digits));
    if (!text.contains('.') && !text.contains('e'))
        text += ".0";
    return text;
}

} // namespace shadowlab
