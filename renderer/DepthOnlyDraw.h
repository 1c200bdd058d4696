#pragma once

#include "GpuScene.h"
#include "ShaderProgram.h"

#include <glm/mat4x4.hpp>

#include <memory>

namespace shadowlab {

// Depth-only drawing of a scene's items through one matrix (shaders/depth.vert, depth.frag):
// the shadow pass's casters from the light and the sdsm prepass's whole view from the camera.
// Cut-out items draw with the ALPHA_CUTOUT variant, compiled on the first one drawn, which
// discards where their mask is clear (shaders/cutout.glsl).
class DepthOnlyDraw {
public:
    // `fullResolutionMask`: read masks at full resolution (the light's passes, as the reference
    // traces them), else as the lit pass reads them.
    DepthOnlyDraw(GlFunctions* gl, bool fullResolutionMask);

    struct Items {
        glm::dmat4 viewProjection{1.0};     // object-relative positions go through it times each item's model
        glm::dmat4 culling{1.0};            // items outside this frustum are left out
        bool clampDepth = false;            // culling keeps what lies before the near plane (depth clamp)
        bool castersOnly = false;
        // The light the casters are drawn for: what shadows nothing under it is left out (shadowsNothing).
        const LightFrame* light = nullptr;
        bool cutouts = true;                // cut-outs through their masks; false: whole
        CasterSet casters = CasterSet::All; // the still or moving items alone (a cache's draws)
    };
    // Draws the items into the bound framebuffer with the raster state as set; leaves texture unit
    // 0 active with nothing bound. Returns the draw calls.
    int draw(const GpuScene& scene, const Items& items);

    bool hasCutoutVariant() const { return m_cutout != nullptr; }

private:
    struct Variant {
        Variant(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint mvp, alphaCutoff;
    };

    GlFunctions* m_gl;
    bool m_fullResolutionMask;
    Variant m_plain;
    std::unique_ptr<Variant> m_cutout;
};

} // namespace shadowlab
