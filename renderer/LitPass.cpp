#include "LitPass.h"

#include "PassState.h"
#include "RenderError.h"
#include "MomentMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr GLuint kDiffuseUnit = 0;
constexpr GLuint kShadowUnit = 1;
constexpr GLuint kContactUnit = 8;     // after the shadow samplers and the min/max depth mip
constexpr GLuint kPageTableUnit = 9;   // a virtual map's page table

} // namespace

LitPass::Program::Program(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("lit.vert"), QStringLiteral("lit.frag"), defines),
      model(program.uniform("uModel")),
      normalMatrix(program.uniform("uNormalMatrix")),
      modelViewProjection(program.uniform("uModelViewProjection")),
      shadowModel(program.uniform("uShadowModel")),
      receives(program.uniform("uReceives")),
      selfShadowing(program.uniform("uSelfShadowing")),
      ownFacets(program.uniform("uOwnFacets")),
      alphaCutoff(program.uniform("uAlphaCutoff")),
      shadowWorld(program.uniform("uShadowWorld")),
      normalOffset(program.uniform("uNormalOffset")),
      biasSlope(program.uniform("uBiasSlope")),
      biasMin(program.uniform("uBiasMin")),
      shadowSlice(program.uniform("uShadowSlice")),
      exponentPositive(program.uniform("uExponentPositive")),
      exponentNegative(program.uniform("uExponentNegative")),
      diffuse(program.uniform("uDiffuse")),
      shadowMap(program.uniform("uShadowMap")),
      shadowDepth(program.uniform("uShadowDepth")),
      shadowMoments(program.uniform("uShadowMoments")),
      depthRange(program.uniform("uDepthRange")),
      cameraDepths(program.uniform("uCameraDepths")),
      virtualPageTable(program.uniform("uVirtualPageTable")),
      depthSlices(defines.contains(QStringLiteral("DEPTH_SLICES")))
{
}

LitPass::LitPass(GlFunctions* gl)
    : m_gl(gl), m_lookupSamples(gl, GL_SAMPLES_PASSED), m_plainSamples(gl, GL_SAMPLES_PASSED), m_programs(gl), m_viewBlock(gl), m_frameBlock(gl),
      m_virtualBlock(gl), m_reachDraws(gl)
{
}

QStringList LitPass::variantDefines(const FramePlan& plan, const Variant& variant)
{
    const Settings& settings = plan.settings;
    const bool measure = variant.measure, reversedDepth = variant.reversedDepth, outOfReach = variant.outOfReach, cutout = variant.cutout;
    QStringList defines;
    // Without lookups (shadows off, or receivers out of reach) no technique, bias or early-out
    // code is compiled, so every technique shares that variant.
    const bool lookups = plan.shadows && !outOfReach;
    const ShadowTechnique& technique = *plan.technique;
    if (lookups) {
        defines << QStringLiteral("SHADOW_TECHNIQUE \"%1\"").arg(technique.shaderFile) << technique.defines(settings);
        if (plan.lookupBlurRadius > 0)
            defines << QStringLiteral("MOMENTS_LOOKUP_BLUR %1").arg(plan.lookupBlurRadius);
    } else
        defines << QStringLiteral("SHADOW_TECHNIQUE \"shadow_unreached.glsl\"") << QStringLiteral("OUT_OF_REACH");
    if (plan.shadows)
        defines << QStringLiteral("SHADOWS");
    if (settings.light.projection == LightProjection::Perspective)
        defines << QStringLiteral("LIGHT_PERSPECTIVE");
    if (settings.light.type == LightType::Spot)
        defines << QStringLiteral("LIGHT_SPOT");
    // A warp asked for but declined in every view (LightWarp.h) keeps the plain lookups.
    if (plan.shadows && plan.lightWarp && variant.warped)
        defines << QStringLiteral("LIGHT_WARP");
    if (plan.shadows && plan.severalViews) {
        defines << QStringLiteral("SHADOW_VIEWS") << (settings.light.type == LightType::Point ? QStringLiteral("LIGHT_POINT") : QStringLiteral("CASCADES"));
        if (settings.shadow.showCascades)
            defines << QStringLiteral("SHOW_CASCADES");
    }
    if (plan.virtualMap && lookups) {
        defines << QStringLiteral("VIRTUAL_MAP");
        if (settings.shadow.showCascades)
            defines << QStringLiteral("SHOW_CASCADES");     // tinted by the level read
    }
    if (plan.shadows && reversedDepth)
        defines << QStringLiteral("REVERSED_Z");
    // A depth map drawn into slices (map.slices) is read through the slice its last draw wrote.
    // The plan keeps the maps that are never sliced (cascades, perspective, virtual, or under
    // the hardware profile) on the variant without.
    if (lookups && readsDepthSlices(plan, reversedDepth))
        defines << QStringLiteral("DEPTH_SLICES");
    if (lookups && settings.bias.space == BiasSpace::Depth)
        defines << QStringLiteral("BIAS_DEPTH");
    else if (lookups && settings.bias.space == BiasSpace::Texel)
        defines << QStringLiteral("BIAS_TEXEL");
    if (lookups && settings.bias.receiverPlane)
        defines << QStringLiteral("RECEIVER_PLANE");
    // Filtered moments read their own bias (filter.moment_bias); depth comparisons the footprint's.
    if (lookups && settings.bias.footprint && !plan.moments) {
        defines << QStringLiteral("FOOTPRINT_BIAS");
        // Each tap's growth, unless the pass culls front faces (bias.cull_front, closed casters):
        // a lit surface's own depth is then not in the map, so no far tap can shadow it, and the
        // growth only lets light leak at contacts. The lookup's own texel keeps its clearance,
        // which thin parts and terminators still need (docs/techniques.md#bias measures both).
        if (!settings.bias.cullFront)
            defines << QStringLiteral("FOOTPRINT_TAPS");
        // A blocker search (pcss, dpcf) reads the whole region a disk light's blockers may lie
        // in, many texels wide: its growth is capped at 10, not 3 (shadow_lookup.glsl's
        // growthSlope), or a grazing receiver's own surface reads as blockers across it.
        if (technique.searchesBlockers)
            defines << QStringLiteral("BLOCKER_SEARCH");
    }
    // A smooth-shaded caster's facets that face away from the light are in its own shadow,
    // whatever its normals say (shadow_lookup.glsl's ownFacetVisibility): with a lookup or
    // without, as facing away is, so the reach's two variants shade alike.
    if (plan.shadows && variant.ownFacets)
        defines << QStringLiteral("OWN_FACETS");
    if (lookups && plan.depthRange)
        defines << QStringLiteral("DEPTH_RANGE");
    if (lookups && plan.earlyOut)
        defines << QStringLiteral("EARLY_OUT");
    // Both sides of the reach march: a receiver no caster reaches in the map has none in view either.
    if (plan.contactShadows)
        defines << QStringLiteral("CONTACT_SHADOWS");
    if (settings.shading.model == ShadingModel::Phong)
        defines << QStringLiteral("SHADING_PHONG");
    if (cutout)
        defines << QStringLiteral("ALPHA_CUTOUT");
    if (measure)
        defines << QStringLiteral("MEASURE");
    else if (settings.shading.texelDensity && plan.shadows)
        defines << QStringLiteral("TEXEL_DENSITY");   // a view only: never in what is measured
    if (!measure && settings.shading.shadowOnly && plan.shadows)
        defines << QStringLiteral("SHADOW_ONLY");     // likewise
    return defines;
}

bool LitPass::readsDepthSlices(const FramePlan& plan, bool reversedDepth)
{
    const std::vector<ShadowSampler>& samplers = plan.technique->samplers;
    const bool readsDepth = std::any_of(samplers.begin(), samplers.end(), [](ShadowSampler s) { return s != ShadowSampler::Moments; });
    return plan.shadows && readsDepth && ShadowMap::slices(plan.slices, plan.settings.map.format, reversedDepth);
}

LitPass::Program& LitPass::programFor(const FramePlan& plan, const Variant& variant)
{
    return m_programs.get(variantDefines(plan, variant));
}

LitPass::Programs LitPass::programsFor(const GpuScene& scene, const FramePlan& plan, Variant variant)
{
    variant.cutout = false;
    variant.ownFacets = scene.hasSmoothCasters();
    Programs p{&programFor(plan, variant)};
    if (scene.hasCutouts()) {
        variant.cutout = true;
        p.cutout = &programFor(plan, variant);
    }
    return p;
}

void LitPass::uploadViews(const CameraFrame& camera, const ShadowMap& map, const glm::dmat4& slice)
{
    const ShadowViewFrames& views = *m_views;
    ShadowViewBlock block;
    block.uShadowViewCount = int(std::min<std::size_t>(views.frames.size(), kMaxShadowViews));
    const glm::dmat4 fromCamera = glm::translate(glm::dmat4(1.0), camera.position);
    const glm::dvec2 tileUv(1.0 / map.columns(), 1.0 / map.rows());
    for (int i = 0; i < block.uShadowViewCount; ++i) {
        const ShadowView& view = views.set.views[std::size_t(i)];
        const LightFrame& frame = views.frames[std::size_t(i)];
        // The view's [0, 1] square to its tile of the map; on homogeneous coordinates, so it
        // holds for perspective views too.
        glm::dmat4 toTile(1.0);
        toTile[0][0] = tileUv.x;
        toTile[1][1] = tileUv.y;
        toTile[3][0] = view.column * tileUv.x;
        toTile[3][1] = view.row * tileUv.y;
        const glm::dmat4 shadowMatrix = slice * frame.depthShadowMatrix;
        block.uShadowViewMatrix[i] = glm::mat4(toTile * shadowMatrix * fromCamera);
        block.uShadowViewTile[i] = glm::vec4(float(view.column * tileUv.x), float(view.row * tileUv.y), float((view.column + 1) * tileUv.x),
                                             float((view.row + 1) * tileUv.y));
        block.uShadowViewUvWorldDepth[i] = glm::vec4(float(frame.volume.width() * map.columns()), float(frame.volume.height() * map.rows()),
                                                     float(frame.volume.nearPlane), float(frame.volume.farPlane));
        // An ortho view's depth change per world unit toward the light (AFFINE_VIEW), in double.
        block.uShadowViewTexelRay[i] = glm::vec4(float(texelWorldSize(frame.volume, map.size())),
                                                 float((shadowMatrix * glm::dvec4(-frame.direction, 0.0)).z), 0.0f, 0.0f);
    }
    m_viewBlock.upload(block);
}

void LitPass::uploadFrame(const CameraFrame& camera, const LightFrame& light, const FramePlan& plan, const ShadowMap* map, bool readsRange,
                          const DepthRangePass* depthRange)
{
    const Settings& settings = plan.settings;
    LitFrameBlock f;
    // Camera-relative: differences of large coordinates are taken in double here, not in float
    // on the GPU.
    f.uLightPosition = glm::vec3(light.position - camera.position);
    f.uLightDirection = glm::vec3(light.direction);
    if (settings.light.type == LightType::Spot) {
        const double half = glm::radians(settings.light.fov) * 0.5;
        f.uSpotCone = glm::vec2(float(std::cos(half)), float(std::cos(half * (1.0 - settings.light.falloff))));
    }
    if (map != nullptr) {
        if (m_views == nullptr || m_views->frames.empty())
            throw RenderError(QStringLiteral("the light's views were not fitted before the lit pass"));
        f.uShadowTexel = glm::vec2(1.0f / float(map->width()), 1.0f / float(map->height()));
        f.uNormalOffsetTexels = float(settings.bias.normal);   // several views
        const TechniqueShaderValues t = plan.technique->shaderValues(settings);
        f.uBleeding = t.bleeding;
        f.uMomentBias = t.momentBias;
        f.uLightSize = t.lightSize;
        f.uPoissonRadius = t.poissonRadius;
        const ShadowViewFrames& views = *m_views;
        if (views.set.cascaded) {
            for (std::size_t i = 0; i < views.set.views.size() && i < 4; ++i) {
                const ShadowView& view = views.set.views[i];
                f.uCascadeFar[int(i)] = float(view.splitFar);
                f.uCascadeBlendStart[int(i)] = float(view.splitFar - settings.shadow.blend * (view.splitFar - view.splitNear));
            }
            // Cascades are slices of the view depth of the camera they were fitted to.
            const CameraFrame& fitted = views.camera;
            f.uViewForward = glm::vec3(-glm::dvec3(fitted.view[0][2], fitted.view[1][2], fitted.view[2][2]));
            f.uViewOrigin = glm::vec3(fitted.position - camera.position);
        }
    }
    if (plan.contactShadows) {
        f.uCameraViewProjection = glm::mat4(camera.viewProjection * glm::translate(glm::dmat4(1.0), camera.position));
        f.uCameraForward = glm::vec3(-camera.view[0][2], -camera.view[1][2], -camera.view[2][2]);
        f.uContactLength = float(settings.contact.length);
        f.uContactThickness = float(settings.contact.thickness);
        f.uContactSteps = settings.contact.steps;
    }
    if (readsRange) {
        f.uDepthRangeLevels = std::min(depthRange->levels(), kMaxDepthRangeLevels);
        for (int level = 0; level < f.uDepthRangeLevels; ++level) {
            const QPoint at = depthRange->levelOrigin(level);
            const QSize size = depthRange->levelSize(level);
            f.uDepthRangeLevel[level] = glm::ivec4(at.x(), at.y(), size.width(), size.height());
        }
    }
    m_frameBlock.upload(f);
    if (map != nullptr && m_virtualMap && plan.virtualMap) {
        if (m_virtualMap->block.uVirtualLevels == 0)
            throw RenderError(QStringLiteral("shadow.virtual's pages were not requested before the lit pass"));
        m_virtualBlock.upload(m_virtualMap->block);
    }
}

void LitPass::setVariantUniforms(const Programs& programs, const CameraFrame& camera, const LightFrame& light, const FramePlan& plan,
                                 const ShadowMap* map, bool readsRange)
{
    const Settings& settings = plan.settings;
    // A variant compiled with DEPTH_SLICES compares in the slice's stored depth; any other in
    // conventional depth (one without lookups still takes one for a measurement). Both of a
    // frame's programs (plain and cut-out) are compiled alike there.
    const glm::dmat4 slice = programs.plain->depthSlices ? m_sliceMatrix : glm::dmat4(1.0);
    if (map != nullptr)
        uploadViews(camera, *map, slice);
    const MomentWarp warp = momentWarp(settings);
    for (Program* p : {programs.plain, programs.cutout}) {
        if (p == nullptr)
            continue;
        p->program.bind();
        p->program.set(p->diffuse, int(kDiffuseUnit));
        p->shadowMatrix = slice * light.depthShadowMatrix;
        if (map == nullptr)
            continue;
        // The bias as set: a bias in texels is scaled by each view's texel in the shader, one in
        // depth units by the slice the lookups compare in.
        const double depthUnit = settings.bias.space == BiasSpace::Depth ? slice[2][2] : 1.0;
        p->program.set(p->biasSlope, float(settings.bias.slope * depthUnit));
        p->program.set(p->biasMin, float(settings.bias.min * depthUnit));
        p->program.set(p->shadowSlice, map->slice().uniform());
        p->program.set(p->exponentPositive, float(warp.positive));
        p->program.set(p->exponentNegative, float(warp.negative));
        // One view's position is taken in the vertex stage, with the normal offset in world units
        // from its texel (at unit distance for a perspective light), the wider axis.
        p->program.set(p->normalOffset, float(settings.bias.normal * texelWorldSize(light.volume, map->size())));
        p->program.set(p->shadowWorld, glm::mat4(p->shadowMatrix));
        const std::vector<ShadowSampler>& samplers = plan.technique->samplers;
        for (std::size_t i = 0; i < samplers.size(); ++i) {
            const GLint sampler = samplers[i] == ShadowSampler::Moments      ? p->shadowMoments
                                  : samplers[i] == ShadowSampler::RawNearest ? p->shadowDepth
                                                                             : p->shadowMap;
            p->program.set(sampler, int(kShadowUnit + GLuint(i)));
        }
        if (readsRange)
            p->program.set(p->depthRange, int(kShadowUnit + GLuint(samplers.size())));
        p->program.set(p->virtualPageTable, int(kPageTableUnit));
        p->program.set(p->cameraDepths, int(kContactUnit));
    }
}

bool LitPass::boundTargetHasStencil() const
{
    GLint framebuffer = 0;
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
    const GLenum attachment = framebuffer == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    GLint type = GL_NONE;
    m_gl->glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE)
        return false;
    GLint bits = 0;
    m_gl->glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
    return bits > 0;
}

void LitPass::drawObjects(const Programs& programs, const GpuScene& scene, const CameraFrame& camera, const ReachDraws::Order& order)
{
    const auto& items = scene.drawItems();
    const glm::dmat4 toCamera = glm::translate(glm::dmat4(1.0), -camera.position);
    Program* bound = nullptr;
    for (const auto& [distance, i] : order) {
        const DrawItem& item = items[i];
        const bool cutout = item.alphaCutoff > 0.0f && programs.cutout != nullptr;
        Program& p = cutout ? *programs.cutout : *programs.plain;
        if (&p != bound) {
            p.program.bind();
            bound = &p;
        }
        p.program.set(p.model, glm::mat4(toCamera * item.model));
        p.program.set(p.normalMatrix, glm::mat3(item.normalMatrix));
        p.program.set(p.modelViewProjection, glm::mat4(camera.viewProjection * item.model));
        p.program.set(p.shadowModel, glm::mat4(p.shadowMatrix * item.model));
        p.program.set(p.receives, int(item.receivesShadow));
        // A floor left out of the map cannot shadow itself: its lookups need no footprint bias.
        p.program.set(p.selfShadowing, int(!(m_floorsLeftOutFor && shadowsNothing(item, *m_floorsLeftOutFor))));
        p.program.set(p.ownFacets, int(item.castsShadow && item.smoothShaded));
        if (cutout)
            p.program.set(p.alphaCutoff, item.alphaCutoff);
        m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        scene.draw(item);
    }
}

void LitPass::clearTarget(bool measure)
{
    const GLfloat clearColour[4] = {0.11f, 0.12f, 0.15f, 1.0f};
    m_gl->glClearColor(clearColour[0], clearColour[1], clearColour[2], clearColour[3]);
    m_gl->glClearDepth(1.0);
    m_gl->glClearStencil(0);
    m_gl->glStencilMask(0xff);
    m_gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (measure) {
        const GLfloat background[4] = {0.0f, 0.0f, 0.0f, 0.0f}; // mask 0: no surface
        m_gl->glClearBufferfv(GL_COLOR, 1, background);
        m_gl->glClearBufferfv(GL_COLOR, 2, background);
        m_gl->glClearBufferfv(GL_COLOR, 3, clearColour);    // the background shaded again is itself
        m_gl->glClearBufferfv(GL_COLOR, 4, background);
    }
}

void LitPass::bindShadowTextures(const FramePlan& plan, const ShadowMap& map, const MomentsMap* moments, const DepthRangePass* depthRange)
{
    // Each sampler the technique's row asks for reads the map on a unit of its own.
    const std::vector<ShadowSampler>& samplers = plan.technique->samplers;
    for (std::size_t i = 0; i < samplers.size(); ++i) {
        const GLuint unit = kShadowUnit + GLuint(i);
        const bool readsMoments = samplers[i] == ShadowSampler::Moments;
        m_gl->glActiveTexture(GL_TEXTURE0 + unit);
        m_gl->glBindTexture(GL_TEXTURE_2D, readsMoments ? moments->texture() : map.texture());
        m_gl->glBindSampler(unit, readsMoments ? moments->sampler() : map.sampler(samplers[i]));
    }
    if (depthRange) {
        const GLuint unit = kShadowUnit + GLuint(samplers.size());
        m_gl->glActiveTexture(GL_TEXTURE0 + unit);
        m_gl->glBindTexture(GL_TEXTURE_2D, depthRange->texture());
        m_gl->glBindSampler(unit, 0);
    }
    m_gl->glActiveTexture(GL_TEXTURE0 + kDiffuseUnit);
}

void LitPass::unbindShadowTextures(const FramePlan& plan, bool readsRange)
{
    for (std::size_t i = 0; i < plan.technique->samplers.size() + (readsRange ? 1 : 0); ++i) {
        m_gl->glActiveTexture(GL_TEXTURE0 + kShadowUnit + GLuint(i));
        m_gl->glBindTexture(GL_TEXTURE_2D, 0);
        m_gl->glBindSampler(kShadowUnit + GLuint(i), 0);
    }
    m_gl->glActiveTexture(GL_TEXTURE0);
}

void LitPass::drawMaskedOrder(const Programs& p, const GpuScene& scene, const CameraFrame& camera, const ReachDraws::Order& everywhere,
                              const ReachDraws::Order& masked, GLenum stencilFunc, const std::vector<QRect>* scissors)
{
    drawObjects(p, scene, camera, everywhere);
    if (masked.empty())
        return;
    m_gl->glEnable(GL_STENCIL_TEST);
    m_gl->glStencilFunc(stencilFunc, 1, 0xff);
    if (!scissors) {
        drawObjects(p, scene, camera, masked);
    } else {
        // Once per rectangle: the rasteriser bins only what lies inside it. The rectangles do
        // not overlap but for their pixel of margin (ShadowReach::screenRects), where the depth
        // test keeps what the first one drew.
        m_gl->glEnable(GL_SCISSOR_TEST);
        for (const QRect& scissor : *scissors) {
            m_gl->glScissor(scissor.x(), scissor.y(), scissor.width(), scissor.height());
            drawObjects(p, scene, camera, masked);
        }
    }
    m_gl->glDisable(GL_SCISSOR_TEST);
    m_gl->glDisable(GL_STENCIL_TEST);
}

namespace {

// What the lit pass reads must have been drawn: a moments map for a moment technique (`shadowMap`:
// null without shadows), the min/max mip for penumbra-only filtering (`range`: whether it is
// read), the camera's depth for contact shadows (`contactDepth`: 1 without them).
void checkInputs(const FramePlan& plan, const ShadowMap* shadowMap, bool range, const DepthRangePass* depthRange, const MomentsMap* moments,
                 GLuint contactDepth)
{
    if (shadowMap != nullptr && plan.moments && (moments == nullptr || moments->size() != shadowMap->size()))
        throw RenderError(QStringLiteral("filter.mode=%1 reads a moments map, which was not rendered").arg(plan.technique->key));
    if (range && (depthRange == nullptr || depthRange->levels() == 0))
        throw RenderError(QStringLiteral("filter.early_out needs the shadow map's min/max depth mip, which was not built"));
    if (contactDepth == 0)
        throw RenderError(QStringLiteral("contact.enabled needs the camera's depth of the casters, which was not drawn"));
}

// `texture` on `unit` with no sampler object, then `after` active again.
void bindUnit(GlFunctions* gl, GLuint unit, GLuint texture, GLenum after = GL_TEXTURE0 + kDiffuseUnit)
{
    gl->glActiveTexture(GL_TEXTURE0 + unit);
    gl->glBindTexture(GL_TEXTURE_2D, texture);
    if (texture != 0)
        gl->glBindSampler(unit, 0);
    gl->glActiveTexture(after);
}

} // namespace

int LitPass::render(const GpuScene& scene, const CameraFrame& camera, const LightFrame& light, const FramePlan& plan,
                    const ShadowMap* map, const RenderTarget& target, bool measure, const DepthRangePass* depthRange,
                    const MomentsMap* moments)
{
    const bool shadows = plan.shadows && map != nullptr;
    const bool readsRange = plan.depthRange && map != nullptr;
    m_floorsLeftOutFor = plan.settings.bias.skipFloors ? &light : nullptr;
    const bool contact = shadows && plan.contactShadows;
    checkInputs(plan, shadows ? map : nullptr, readsRange, depthRange, moments, contact ? m_contactDepth : GLuint(1));

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    m_reachDraws.sort(scene, camera, shadows, m_reach, shadows && m_reach != nullptr && boundTargetHasStencil());
    PassState state;
    state.viewport = QRect(QPoint(0, 0), target.size);
    state.depthTest = true;
    state.cullFace = GL_BACK;
    applyPassState(m_gl, state);
    clearTarget(measure);
    // The lookups' draws stay inside the reach's rectangle on screen, so the rasteriser skips
    // the rest of the frame for them.
    const std::vector<QRect> lookupRects = m_reachDraws.drawMask(camera, target.size);
    if (m_reachDraws.use().masked)
        applyPassState(m_gl, state);
    if (shadows)
        bindShadowTextures(plan, *map, moments, readsRange ? depthRange : nullptr);
    if (contact)
        bindUnit(m_gl, kContactUnit, m_contactDepth);
    const bool pageTable = shadows && plan.virtualMap && m_virtualMap != nullptr;
    if (pageTable)
        bindUnit(m_gl, kPageTableUnit, m_virtualMap->pageTable);
    const ShadowMap* shadowMap = shadows ? map : nullptr;
    m_sliceMatrix = shadows ? map->slice().matrix() : glm::dmat4(1.0);
    Variant variant{.measure = measure, .reversedDepth = light.reversedDepth, .warped = light.volume.warped};
    if (m_views) {
        for (const LightFrame& frame : m_views->frames)
            variant.warped = variant.warped || frame.volume.warped;
    }
    uploadFrame(camera, light, plan, shadowMap, readsRange, depthRange);
    const ReachDraws& r = m_reachDraws;
    if (!r.lookup().empty() || !r.maskedLookup().empty()) {
        const Programs lookup = programsFor(scene, plan, variant);
        setVariantUniforms(lookup, camera, light, plan, shadowMap, readsRange);
        if (m_counting)
            m_lookupSamples.begin();
        drawMaskedOrder(lookup, scene, camera, r.lookup(), r.maskedLookup(), GL_EQUAL, &lookupRects);
        if (m_counting)
            m_lookupSamples.end();
    }
    if (!r.plain().empty() || !r.maskedPlain().empty()) {
        variant.outOfReach = true;
        const Programs plain = programsFor(scene, plan, variant);
        setVariantUniforms(plain, camera, light, plan, shadowMap, readsRange);
        if (m_counting)
            m_plainSamples.begin();
        drawMaskedOrder(plain, scene, camera, r.plain(), r.maskedPlain(), GL_NOTEQUAL, nullptr);
        if (m_counting)
            m_plainSamples.end();
    }
    m_fragments = {.lookup = std::max<std::int64_t>(m_lookupSamples.result(), 0), .plain = std::max<std::int64_t>(m_plainSamples.result(), 0)};
    const int draws = r.use().lookupDraws + r.use().plainDraws;

    m_gl->glBindVertexArray(0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    if (shadows)
        unbindShadowTextures(plan, readsRange);
    for (const auto& [unit, used] : {std::pair{kContactUnit, contact}, std::pair{kPageTableUnit, pageTable}}) {
        if (used)
            bindUnit(m_gl, unit, 0, GL_TEXTURE0);
    }
    m_gl->glDisable(GL_CULL_FACE);
    return draws;
}

} // namespace shadowlab
