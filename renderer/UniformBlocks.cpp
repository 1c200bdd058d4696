#include "UniformBlocks.h"

#include <array>

namespace shadowlab {

namespace {

// The GLSL declaration of a block from its field list: each member under its C++ name and type,
// with its note as a comment, array sizes as the constants' own #defines.
#define SHADOWLAB_GLSL_FIELD(type, name, note) \
    glsl += QByteArray("    ") + std140::glslType<std140::type>() + " " #name ";   // " note "\n";
#define SHADOWLAB_GLSL_ARRAY(type, name, count, note) \
    glsl += QByteArray("    ") + std140::glslType<std140::type>() + " " #name "[" #count "];   // " note "\n";
#define SHADOWLAB_MEMBER_FIELD(type, name, note) std140::Member{#name, offsetof(Block, name), 0},
#define SHADOWLAB_MEMBER_ARRAY(type, name, count, note) std140::Member{#name "[0]", offsetof(Block, name), sizeof(std140::type)},

#define SHADOWLAB_DECLARE_BLOCK(BlockType, FIELDS)                                                                   \
    UniformBlockDeclaration declare##BlockType()                                                                     \
    {                                                                                                                \
        using Block = BlockType;                                                                                     \
        static const auto members = std::to_array<std140::Member>({FIELDS(SHADOWLAB_MEMBER_FIELD, SHADOWLAB_MEMBER_ARRAY)}); \
        QByteArray glsl = QByteArray("layout(std140) uniform ") + Block::kName + " {\n";                             \
        FIELDS(SHADOWLAB_GLSL_FIELD, SHADOWLAB_GLSL_ARRAY)                                                           \
        glsl += "};\n";                                                                                              \
        return {Block::kName, Block::kBinding, glsl, members, sizeof(Block)};                                        \
    }

SHADOWLAB_DECLARE_BLOCK(ShadowViewBlock, SHADOWLAB_SHADOW_VIEW_BLOCK)
SHADOWLAB_DECLARE_BLOCK(LitFrameBlock, SHADOWLAB_LIT_FRAME_BLOCK)
SHADOWLAB_DECLARE_BLOCK(VirtualMapBlock, SHADOWLAB_VIRTUAL_MAP_BLOCK)

} // namespace

std::span<const UniformBlockDeclaration> uniformBlocks()
{
    static const std::array<UniformBlockDeclaration, 3> blocks{declareShadowViewBlock(), declareLitFrameBlock(), declareVirtualMapBlock()};
    return blocks;
}

const UniformBlockDeclaration* uniformBlock(const QString& name)
{
    for (const UniformBlockDeclaration& block : uniformBlocks()) {
        if (name == QLatin1String(block.name))
            return &block;
    }
    return nullptr;
}

} // namespace shadowlab
