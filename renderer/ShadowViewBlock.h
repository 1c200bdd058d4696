#pragma once

#include "ShadowViews.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>

namespace shadowlab {

// The lit pass's shadow views as one std140 uniform block, `ShadowViewBlock` of
// shaders/shadow_lookup.glsl: one upload a frame (LitPass::setViewUniforms) instead of a uniform
// array a field, looked up by name. The fields follow the GLSL declaration one for one, at the
// offsets std140 gives them (every member a multiple of 16 bytes, so no padding of its own);
// tst_LightTypes::shadowViewBlockMatchesTheShader compares them with the driver's.
struct ShadowViewStd140 {
    glm::mat4 matrix{1.0f};             // camera-relative world -> map uv (of the whole map) and the view's depth
    glm::vec4 tile{0.0f};               // the view's tile in map uv: min xy, max xy
    glm::vec4 uvWorldDepth{0.0f};       // world size of the map's uv square at the view's scale (xy); near, far (zw)
    glm::vec4 texelRay{0.0f};           // world size of a texel; depth change per world unit toward the light (ortho); 0, 0
};

struct ShadowViewBlockStd140 {
    ShadowViewStd140 views[kMaxShadowViews];
    std::int32_t count = 0;
    std::int32_t padding[3] = {0, 0, 0};
};

// The uniform buffer binding the lit pass reads the block from.
inline constexpr unsigned kShadowViewBlockBinding = 0;

static_assert(sizeof(ShadowViewStd140) == 112, "std140: a mat4 and three vec4");
static_assert(offsetof(ShadowViewStd140, tile) == 64 && offsetof(ShadowViewStd140, uvWorldDepth) == 80 && offsetof(ShadowViewStd140, texelRay) == 96);
static_assert(offsetof(ShadowViewBlockStd140, count) == 112 * kMaxShadowViews, "std140: the count after the array");

} // namespace shadowlab
