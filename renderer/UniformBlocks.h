#pragma once

#include "GlObject.h"
#include "ShadowViews.h"
#include "ShaderConstants.h"
#include "VirtualPages.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <QByteArray>

#include <cstddef>
#include <span>
#include <type_traits>

namespace shadowlab {

// The shaders' uniform blocks, each declared once, here: one list of fields makes both the C++
// struct a pass fills and uploads whole, and the GLSL declaration a shader pulls in with
// `#include BlockName` (ShaderProgram; guarded, so that every file that reads it says so). Every
// program is linked with each block it declares at the block's binding.
//
// The layout is std140, which C++ follows member for member because each member is aligned as
// std140 aligns it (4 bytes for a scalar, 8 for a vec2, 16 for a vec3, vec4 and mat4). std140
// gives an array a stride of 16 bytes whatever its element, so arrays here are of 16-byte
// elements only. tst_SharedShaderCode compares every offset with the driver's.
namespace std140 {
using Float = float;
using Int = int;
using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using IVec4 = glm::ivec4;
using Mat4 = glm::mat4;

template<class T>
constexpr std::size_t alignment()
{
    if constexpr (std::is_same_v<T, Float> || std::is_same_v<T, Int>)
        return 4;
    else if constexpr (std::is_same_v<T, Vec2>)
        return 8;
    else
        return 16;
}

template<class T>
constexpr const char* glslType()
{
    if constexpr (std::is_same_v<T, Float>)
        return "float";
    else if constexpr (std::is_same_v<T, Int>)
        return "int";
    else if constexpr (std::is_same_v<T, Vec2>)
        return "vec2";
    else if constexpr (std::is_same_v<T, Vec3>)
        return "vec3";
    else if constexpr (std::is_same_v<T, Vec4>)
        return "vec4";
    else if constexpr (std::is_same_v<T, IVec4>)
        return "ivec4";
    else
        return "mat4";
}

// A member as the driver lays it out: its name as GLSL queries it ("uShadowViewMatrix[0]" for an array),
// its offset in bytes and, for an array, the stride between elements (0 otherwise).
struct Member {
    const char* name;
    std::size_t offset;
    std::size_t arrayStride;
};
} // namespace std140

// A block's GLSL declaration and its members' layout, for the shader loader and the tests.
struct UniformBlockDeclaration {
    const char* name;
    unsigned binding;
    QByteArray glsl;                        // "layout(std140) uniform Name { ... };"
    std::span<const std140::Member> members;
    std::size_t size;                       // sizeof the C++ struct
};

#define SHADOWLAB_STD140_FIELD(type, name, note) alignas(std140::alignment<std140::type>()) std140::type name{};
#define SHADOWLAB_STD140_ARRAY(type, name, count, note)                                                         \
    static_assert(sizeof(std140::type) % 16 == 0, "std140 arrays here hold 16-byte elements: " #name);         \
    alignas(16) std140::type name[count]{};

// The views of the light the lit pass looks up (shaders/shadow_lookup.glsl), one a tile of the
// map; perspective views' world sizes at unit distance.
#define SHADOWLAB_SHADOW_VIEW_BLOCK(FIELD, ARRAY)                                                                          \
    ARRAY(Mat4, uShadowViewMatrix, kMaxShadowViews, "camera-relative world -> map uv (of the whole map) and the view's depth") \
    ARRAY(Vec4, uShadowViewTile, kMaxShadowViews, "the view's tile in map uv: min xy, max xy")                              \
    ARRAY(Vec4, uShadowViewUvWorldDepth, kMaxShadowViews, "world size of the map's uv square at the view's scale; near, far") \
    ARRAY(Vec4, uShadowViewTexelRay, kMaxShadowViews, "world size of a texel; depth per world unit toward the light (ortho)") \
    FIELD(Int, uShadowViewCount, "views in use")

// The lit pass's frame: the light, the bias and filters' frame-wide values, cascades, contact
// shadows and the min/max depth mip (shaders/lit.vert, lit.frag and what they include).
#define SHADOWLAB_LIT_FRAME_BLOCK(FIELD, ARRAY)                                                                               \
    FIELD(Vec3, uLightPosition, "camera-relative")                                                                            \
    FIELD(Float, uContactLength, "contact shadows: world units")                                                             \
    FIELD(Vec3, uLightDirection, "unit, from the light toward its target")                                                    \
    FIELD(Float, uNormalOffsetTexels, "several views: bias.normal in texels")                                                 \
    FIELD(Vec2, uSpotCone, "cosines of the cone's half-angle and of where its falloff starts")                               \
    FIELD(Vec2, uShadowTexel, "1 / map size")                                                                                 \
    FIELD(Vec4, uCascadeFar, "view depth where each cascade ends (the last: shadow.distance)")                               \
    FIELD(Vec4, uCascadeBlendStart, "view depth where each cascade starts fading into the next")                              \
    FIELD(Vec3, uViewForward, "unit view direction of the camera the cascades were fitted to")                               \
    FIELD(Int, uDepthRangeLevels, "levels of the min/max depth mip")                                                         \
    FIELD(Vec3, uViewOrigin, "... and its position, camera-relative")                                                        \
    FIELD(Float, uBleeding, "moments: [0, 0.95], visibility below it reads as shadow")                                      \
    FIELD(Float, uMomentBias, "moments: least variance, or the blend toward 0.5 (msm)")                                      \
    FIELD(Float, uLightSize, "blocker searches: light.radius / distance to the target (ortho), light.radius (perspective)")  \
    FIELD(Float, uPoissonRadius, "poisson: texels (filter.radius)")                                                          \
    FIELD(Mat4, uCameraViewProjection, "camera-relative world -> clip")                                                      \
    FIELD(Vec3, uCameraForward, "unit view direction")                                                                       \
    FIELD(Float, uContactThickness, "contact shadows: world units")                                                          \
    FIELD(Int, uContactSteps, "contact shadows: steps of the march")                                                         \
    ARRAY(IVec4, uDepthRangeLevel, kMaxDepthRangeLevels, "each mip level's origin in the atlas and its size")

// A virtual map's clipmap (shaders/virtual_pages.glsl): read by its request pass and by the lit
// pass's lookup.
#define SHADOWLAB_VIRTUAL_MAP_BLOCK(FIELD, ARRAY)                                                                  \
    FIELD(Mat4, uVirtualLight, "camera-relative world -> (q0, depth as the pages store it)")                       \
    FIELD(Int, uVirtualLevels, "clipmap levels")                                                                   \
    FIELD(Int, uVirtualLodBias, "levels finer than a texel per pixel (shadow.virtual_lod_bias)")                 \
    FIELD(Int, uVirtualPoolSide, "slots per side of the pool (the map)")                                         \
    FIELD(Float, uVirtualTexel0, "world size of a level-0 texel")                                                 \
    ARRAY(Vec4, uVirtualLevelOffset, kMaxVirtualLevels, "xy: each level's window offset of q0")                   \
    ARRAY(IVec4, uVirtualWrap, kMaxVirtualLevels, "xy: each level's window origin, mod its width (the table wraps)")

struct ShadowViewBlock {
    SHADOWLAB_SHADOW_VIEW_BLOCK(SHADOWLAB_STD140_FIELD, SHADOWLAB_STD140_ARRAY)
    static constexpr const char* kName = "ShadowViewBlock";
    static constexpr unsigned kBinding = 0;
};

struct LitFrameBlock {
    SHADOWLAB_LIT_FRAME_BLOCK(SHADOWLAB_STD140_FIELD, SHADOWLAB_STD140_ARRAY)
    static constexpr const char* kName = "LitFrameBlock";
    static constexpr unsigned kBinding = 1;
};

struct VirtualMapBlock {
    SHADOWLAB_VIRTUAL_MAP_BLOCK(SHADOWLAB_STD140_FIELD, SHADOWLAB_STD140_ARRAY)
    static constexpr const char* kName = "VirtualMapBlock";
    static constexpr unsigned kBinding = 2;
};

// Every block, in binding order.
std::span<const UniformBlockDeclaration> uniformBlocks();
// The block named `name`; null where there is none.
const UniformBlockDeclaration* uniformBlock(const QString& name);

// One block's uniform buffer: upload() replaces its contents whole and binds it at the block's
// binding, where every program that declares the block reads it.
template<class Block>
class UniformBuffer {
public:
    explicit UniformBuffer(GlFunctions* gl) : m_gl(gl) {}

    void upload(const Block& block)
    {
        if (!m_buffer)
            m_buffer = makeBuffer(m_gl);
        m_gl->glBindBuffer(GL_UNIFORM_BUFFER, m_buffer.id());
        m_gl->glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(sizeof(Block)), &block, GL_STREAM_DRAW);
        m_gl->glBindBuffer(GL_UNIFORM_BUFFER, 0);
        bind();
    }
    // Binds the last upload again (another pass may have bound its own since).
    void bind() { m_gl->glBindBufferBase(GL_UNIFORM_BUFFER, Block::kBinding, m_buffer.id()); }

private:
    GlFunctions* m_gl;
    GlBuffer m_buffer;
};

} // namespace shadowlab
