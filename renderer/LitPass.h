#pragma once

#include "DepthRangePass.h"
#include "CountQuery.h"
#include "FramePlan.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "MomentsMap.h"
#include "ProgramCache.h"
#include "ReachDraws.h"
#include "RenderTarget.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"
#include "ShadowReach.h"
#include "ShadowViewFrames.h"
#include "UniformBlocks.h"
#include "VirtualShadowMap.h"

#include <memory>
#include <utility>
#include <vector>

namespace shadowlab {

// What selects a variant besides the frame's plan: what the frame draws and what its light's
// views are like.
struct LitVariant {
    bool measure = false;       // into a measure target (MeasureTarget.h)
    bool reversedDepth = false; // the map has reversed depth
    bool outOfReach = false;    // for receivers no caster reaches: no lookup
    bool cutout = false;        // for cut-out objects (DrawItem::alphaCutoff), only in a scene with them
    bool warped = false;        // a view of the light is warped (light.warp): lookups per pixel
    bool ownFacets = false;     // a caster is smooth-shaded (GpuScene::hasSmoothCasters): OWN_FACETS
};

// Lit pass: shades every object with Blinn-Phong or Phong and the selected shadow filter.
// Only the shader variant in use is compiled (on first use, then kept for switching back).
class LitPass {
public:
    explicit LitPass(GlFunctions* gl);

    // Draws into `target`, which must have a depth buffer. `map` may be null when shadows are off.
    // With `measure` the target must also have four RGBA32F attachments, which receive the
    // camera-relative position and shadow visibility, the geometric normal and a mask
    // (1 facing the light, 2 facing away, 0 background), and the ambient and direct light that
    // the colour is made of (ambient + visibility * direct; the background's ambient is the
    // clear colour). Returns the number of draw calls.
    // `depthRange` is the min/max depth mip of `map` for penumbra-only filtering; it must be
    // current (built from the map as it is) whenever the plan reads it (FramePlan::depthRange). `moments` is the
    // moments map a moment technique reads (its sampler ShadowSampler::Moments); `map` still
    // gives the map's size then.
    int render(const GpuScene& scene, const CameraFrame& camera, const LightFrame& light, const FramePlan& plan,
               const ShadowMap* map, const RenderTarget& target, bool measure = false, const DepthRangePass* depthRange = nullptr,
               const MomentsMap* moments = nullptr);

    // The casters' front and back faces as the camera sees them (CameraDepthPass::texture())
    // that the next render() marches over (FramePlan::contactShadows); not owned.
    void setContactDepth(GLuint texture) { m_contactDepth = texture; }

    // Whether the lookups of `plan` read a depth map drawn into slices (map.slices): their
    // shadow matrix then gives stored depth (DepthSlice::matrix).
    static bool readsDepthSlices(const FramePlan& plan, bool reversedDepth);

    using Variant = LitVariant;
    // The #defines that select the variant for `plan` (exposed for tests and diagnostics).
    static QStringList variantDefines(const FramePlan& plan, const Variant& variant = {});
    int compiledVariantCount() const { return m_programs.size(); }
    // Of those, the variants for cut-out objects (ALPHA_CUTOUT).
    int compiledCutoutVariantCount() const { return m_programs.countWith(QStringLiteral("ALPHA_CUTOUT")); }

    // The light's views the next render() reads (one map, cascades or cube faces, each in its
    // tile of `map`); needed when shadows are on. Not owned; must outlive render().
    void setShadowViews(const ShadowViewFrames* views) { m_views = views; }
    // shadow.virtual: the page table and clipmap the lookups read (null: not a virtual map).
    void setVirtualMap(const VirtualMapUniforms* virtualMap) { m_virtualMap = virtualMap; }
    // Where the next render()'s lookups can find a caster, per object of the scene (computed by
    // the Renderer with the fit): receivers out of reach are shaded without a lookup, and those
    // that straddle it are drawn twice under a stencil mask of the reach where the target has a
    // stencil buffer. A software rasteriser's optimisation (RasteriserTuning::skipsOutOfReach).
    // Null: every receiver looks up. Not owned; must outlive render().
    void setShadowReach(const ShadowReach* reach) { m_reach = reach; }
    // What the last render() did with the reach: receivers drawn with and without a lookup, and
    // whether it drew the stencil mask.
    const ReachDraws::Use& lastReachUse() const { return m_reachDraws.use(); }
    // Whether render() counts the fragments of its draws that look the shadow up and of those
    // that do not (GL_SAMPLES_PASSED; Renderer::setCounting).
    void setCounting(bool counting) { m_counting = counting; }
    struct Fragments {
        std::int64_t lookup = 0;
        std::int64_t plain = 0;
    };
    // The last counted render()'s (zero where it was not counted).
    Fragments lastFragments() const { return m_fragments; }

private:
    // A variant's program and the uniforms it reads outside the blocks (UniformBlocks.h).
    struct Program {
        explicit Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        // Per draw.
        GLint model, normalMatrix, modelViewProjection, shadowModel, receives, selfShadowing, ownFacets, alphaCutoff;
        // Per variant: what depends on whether it compares in a slice's stored depth, and what
        // other programs read too (the slice, the moments' warp).
        GLint shadowWorld, normalOffset, biasSlope, biasMin, shadowSlice, exponentPositive, exponentNegative;
        // Samplers' texture units.
        GLint diffuse, shadowMap, shadowDepth, shadowMoments, depthRange, cameraDepths, virtualPageTable;
        bool depthSlices;               // compiled with DEPTH_SLICES: its lookups compare in stored depth
        glm::dmat4 shadowMatrix{1.0};   // this frame's world -> map, the slice folded in where it reads one
    };

    // A frame's variant for opaque objects and, in a scene with cut-outs, the one for those.
    struct Programs {
        Program* plain = nullptr;
        Program* cutout = nullptr;
    };

    Program& programFor(const FramePlan& plan, const Variant& variant);
    Programs programsFor(const GpuScene& scene, const FramePlan& plan, Variant variant);
    // The frame's blocks, the same for every variant.
    void uploadFrame(const CameraFrame& camera, const LightFrame& light, const FramePlan& plan, const ShadowMap* map, bool readsRange,
                     const DepthRangePass* depthRange);
    // The views' block, with `slice` folded into their matrices (a variant compiled with
    // DEPTH_SLICES compares in stored depth).
    void uploadViews(const CameraFrame& camera, const ShadowMap& map, const glm::dmat4& slice);
    // The uniforms of `programs` outside the blocks, and with shadows the views' block for them.
    void setVariantUniforms(const Programs& programs, const CameraFrame& camera, const LightFrame& light, const FramePlan& plan,
                            const ShadowMap* map, bool readsRange);
    // Whether the framebuffer bound now has stencil bits.
    bool boundTargetHasStencil() const;
    void drawObjects(const Programs& p, const GpuScene& scene, const CameraFrame& camera, const ReachDraws::Order& order);
    // Colour, depth and stencil, and the measurement's targets.
    void clearTarget(bool measure);
    void bindShadowTextures(const FramePlan& plan, const ShadowMap& map, const MomentsMap* moments, const DepthRangePass* depthRange);
    void unbindShadowTextures(const FramePlan& plan, bool readsRange);
    // `everywhere`, then `masked` where the stencil passes `stencilFunc` against 1: once inside
    // each of `scissors` when given (none: not at all), else over the whole target.
    void drawMaskedOrder(const Programs& p, const GpuScene& scene, const CameraFrame& camera, const ReachDraws::Order& everywhere,
                         const ReachDraws::Order& masked, GLenum stencilFunc, const std::vector<QRect>* scissors);

    GlFunctions* m_gl;
    bool m_counting = false;
    CountQuery m_lookupSamples;
    CountQuery m_plainSamples;
    Fragments m_fragments;
    ProgramCache<Program> m_programs;
    const ShadowViewFrames* m_views = nullptr;
    UniformBuffer<ShadowViewBlock> m_viewBlock;
    UniformBuffer<LitFrameBlock> m_frameBlock;
    UniformBuffer<VirtualMapBlock> m_virtualBlock;
    // This frame's conventional-to-stored depth of the map (DepthSlice::matrix), folded into
    // the shadow matrices of the variants compiled with DEPTH_SLICES.
    glm::dmat4 m_sliceMatrix{1.0};
    const VirtualMapUniforms* m_virtualMap = nullptr;
    const ShadowReach* m_reach = nullptr;
    ReachDraws m_reachDraws;            // which receivers look up, and the reach's mask
    GLuint m_contactDepth = 0;
    // The light the shadow pass left floors out for (bias.skip_floors), during render().
    const LightFrame* m_floorsLeftOutFor = nullptr;
};

} // namespace shadowlab
