#include "LitPass.h"

#include "MomentMath.h"
#include "PassState.h"
#include "RenderError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"

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

// Above this share of the frame a mask saves less than drawing the straddling receivers twice
// costs (both halves still run every vertex and set up every triangle).
constexpr double kMaxMaskShare = 0.6;

} // namespace

LitPass::Program::Program(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("lit.vert"), QStringLiteral("lit.frag"), defines),
      model(program.uniform("uModel")),
      normalMatrix(program.uniform("uNormalMatrix")),
      modelViewProjection(program.uniform("uModelViewProjection")),
      shadowModel(program.uniform("uShadowModel")),
      shadowWorld(program.uniform("uShadowWorld")),
      normalOffset(program.uniform("uNormalOffset")),
      diffuse(program.uniform("uDiffuse")),
      receives(program.uniform("uReceives")),
      selfShadowing(program.uniform("uSelfShadowing")),
      shadowMap(program.uniform("uShadowMap")),
      shadowDepth(program.uniform("uShadowDepth")),
      shadowMoments(program.uniform("uShadowMoments")),
      shadowTexel(program.uniform("uShadowTexel")),
      depthRange(program.uniform("uDepthRange")),
      depthRangeLevels(program.uniform("uDepthRangeLevels")),
      lightPosition(program.uniform("uLightPosition")),
      lightDirection(program.uniform("uLightDirection")),
      biasSlope(program.uniform("uBiasSlope")),
      biasMin(program.uniform("uBiasMin")),
      alphaCutoff(program.uniform("uAlphaCutoff")),
      depthSlices(defines.contains(QStringLiteral("DEPTH_SLICES")))
{
}

GLint LitPass::Program::techniqueUniform(const QByteArray& name)
{
    auto it = techniqueUniforms.find(name);
    if (it == techniqueUniforms.end())
        it = techniqueUniforms.emplace(name, program.uniform(name.constData())).first;
    return it->second;
}

LitPass::LitPass(GlFunctions* gl)
    : m_gl(gl), m_lookupSamples(gl, GL_SAMPLES_PASSED), m_plainSamples(gl, GL_SAMPLES_PASSED), m_programs(gl)
{
}

QStringList LitPass::variantDefines(const Settings& settings, const Variant& variant)
{
    const bool measure = variant.measure, reversedDepth = variant.reversedDepth, outOfReach = variant.outOfReach, cutout = variant.cutout;
    QStringList defines;
    // Without lookups (shadows off, or receivers out of reach) no technique, bias or early-out
    // code is compiled, so every technique shares that variant.
    const bool lookups = settings.shadow.enabled && !outOfReach;
    const ShadowTechnique& technique = shadowTechnique(settings.filter.mode);
    if (lookups)
        defines << QStringLiteral("SHADOW_TECHNIQUE \"%1\"").arg(technique.shaderFile) << technique.defines(settings);
    else
        defines << QStringLiteral("SHADOW_TECHNIQUE \"shadow_unreached.glsl\"") << QStringLiteral("OUT_OF_REACH");
    if (settings.shadow.enabled)
        defines << QStringLiteral("SHADOWS");
    if (settings.light.projection == LightProjection::Perspective)
        defines << QStringLiteral("LIGHT_PERSPECTIVE");
    if (settings.light.type == LightType::Spot)
        defines << QStringLiteral("LIGHT_SPOT");
    // A warp asked for but declined in every view (LightWarp.h) keeps the plain lookups.
    if (settings.shadow.enabled && usesLightWarp(settings) && variant.warped)
        defines << QStringLiteral("LIGHT_WARP");
    if (settings.shadow.enabled && usesShadowViews(settings)) {
        defines << QStringLiteral("SHADOW_VIEWS") << (settings.light.type == LightType::Point ? QStringLiteral("LIGHT_POINT") : QStringLiteral("CASCADES"));
        if (settings.shadow.showCascades)
            defines << QStringLiteral("SHOW_CASCADES");
    }
    if (settings.shadow.enabled && settings.shadow.virtualMap && lookups) {
        defines << QStringLiteral("VIRTUAL_MAP");
        if (settings.shadow.showCascades)
            defines << QStringLiteral("SHOW_CASCADES");     // tinted by the level read
    }
    if (settings.shadow.enabled && reversedDepth)
        defines << QStringLiteral("REVERSED_Z");
    // A depth map drawn into slices (map.slices) is read through the slice its last draw wrote.
    // ShadowMap::slicesFor keeps the maps that are never sliced (cascades, perspective, virtual)
    // on the variant without.
    if (lookups && readsDepthSlices(settings, reversedDepth))
        defines << QStringLiteral("DEPTH_SLICES");
    if (lookups && settings.bias.space == BiasSpace::Depth)
        defines << QStringLiteral("BIAS_DEPTH");
    else if (lookups && settings.bias.space == BiasSpace::Texel)
        defines << QStringLiteral("BIAS_TEXEL");
    if (lookups && settings.bias.receiverPlane)
        defines << QStringLiteral("RECEIVER_PLANE");
    // Filtered moments read their own bias (filter.moment_bias); depth comparisons the footprint's.
    if (lookups && settings.bias.footprint && shadowTechnique(settings.filter.mode).map != ShadowMapKind::Moments) {
        defines << QStringLiteral("FOOTPRINT_BIAS");
        // Each tap's growth, unless the pass culls front faces (bias.cull_front, closed casters):
        // a lit surface's own depth is then not in the map, so no far tap can shadow it, and the
        // growth only lets light leak at contacts. The lookup's own texel keeps its clearance,
        // which thin parts and terminators still need (docs/techniques.md#bias measures both).
        if (!settings.bias.cullFront)
            defines << QStringLiteral("FOOTPRINT_TAPS");
    }
    if (lookups && usesDepthRange(settings))
        defines << QStringLiteral("EARLY_OUT");
    // Both sides of the reach march: a receiver no caster reaches in the map has none in view either.
    if (usesContactShadows(settings))
        defines << QStringLiteral("CONTACT_SHADOWS");
    if (settings.shading.model == ShadingModel::Phong)
        defines << QStringLiteral("SHADING_PHONG");
    if (cutout)
        defines << QStringLiteral("ALPHA_CUTOUT");
    if (measure)
        defines << QStringLiteral("MEASURE");
    else if (settings.shading.texelDensity && settings.shadow.enabled)
        defines << QStringLiteral("TEXEL_DENSITY");   // a view only: never in what is measured
    if (!measure && settings.shading.shadowOnly && settings.shadow.enabled)
        defines << QStringLiteral("SHADOW_ONLY");     // likewise
    return defines;
}

bool LitPass::readsDepthSlices(const Settings& settings, bool reversedDepth)
{
    const std::vector<ShadowSampler>& samplers = shadowTechnique(settings.filter.mode).samplers;
    const bool readsDepth = std::any_of(samplers.begin(), samplers.end(), [](ShadowSampler s) { return s != ShadowSampler::Moments; });
    return settings.shadow.enabled && readsDepth && ShadowMap::slices(ShadowMap::slicesFor(settings), settings.map.format, reversedDepth);
}

bool LitPass::usesContactShadows(const Settings& settings)
{
    return settings.shadow.enabled && settings.contact.enabled;
}

bool LitPass::usesDepthRange(const Settings& settings)
{
    return settings.shadow.enabled && settings.filter.earlyOut && shadowTechnique(settings.filter.mode).penumbraOnly;
}

LitPass::Program& LitPass::programFor(const Settings& settings, const Variant& variant)
{
    return m_programs.get(variantDefines(settings, variant));
}

LitPass::Programs LitPass::programsFor(const GpuScene& scene, const Settings& settings, Variant variant)
{
    variant.cutout = false;
    Programs p{&programFor(settings, variant)};
    if (scene.hasCutouts()) {
        variant.cutout = true;
        p.cutout = &programFor(settings, variant);
    }
    return p;
}

void LitPass::setViewUniforms(Program& p, const CameraFrame& camera, const Settings& settings, const ShadowMap& map, const glm::dmat4& slice)
{
    const ShadowViewFrames& views = *m_views;
    const int count = int(std::min<std::size_t>(views.frames.size(), kMaxShadowViews));
    std::vector<glm::mat4> matrices;
    std::vector<glm::vec4> tiles;
    std::vector<glm::vec2> uvWorld, depthRange;
    std::vector<float> texels, rayDepths;
    const glm::dmat4 fromCamera = glm::translate(glm::dmat4(1.0), camera.position);
    const glm::dvec2 tileUv(1.0 / map.columns(), 1.0 / map.rows());
    for (int i = 0; i < count; ++i) {
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
        matrices.emplace_back(toTile * shadowMatrix * fromCamera);
        tiles.emplace_back(float(view.column * tileUv.x), float(view.row * tileUv.y), float((view.column + 1) * tileUv.x),
                           float((view.row + 1) * tileUv.y));
        uvWorld.emplace_back(float(frame.volume.width() * map.columns()), float(frame.volume.height() * map.rows()));
        depthRange.emplace_back(float(frame.volume.nearPlane), float(frame.volume.farPlane));
        texels.push_back(float(texelWorldSize(frame.volume, map.size())));
        // An ortho view's depth change per world unit toward the light (AFFINE_VIEW), in double.
        rayDepths.push_back(float((shadowMatrix * glm::dvec4(-frame.direction, 0.0)).z));
    }
    p.program.set(p.techniqueUniform("uShadowViewCount"), count);
    m_gl->glUniformMatrix4fv(p.techniqueUniform("uShadowViews"), count, GL_FALSE, &matrices[0][0][0]);
    m_gl->glUniform4fv(p.techniqueUniform("uShadowTiles"), count, &tiles[0][0]);
    m_gl->glUniform2fv(p.techniqueUniform("uShadowViewUvWorld"), count, &uvWorld[0][0]);
    m_gl->glUniform2fv(p.techniqueUniform("uShadowViewDepth"), count, &depthRange[0][0]);
    m_gl->glUniform1fv(p.techniqueUniform("uShadowViewTexel"), count, texels.data());
    m_gl->glUniform1fv(p.techniqueUniform("uShadowViewRayDepth"), count, rayDepths.data());
    p.program.set(p.techniqueUniform("uNormalOffsetTexels"), float(settings.bias.normal));   // several views
    if (views.set.cascaded) {
        glm::vec4 far(0.0f), blendStart(0.0f);
        for (int i = 0; i < count && i < 4; ++i) {
            const ShadowView& view = views.set.views[std::size_t(i)];
            far[i] = float(view.splitFar);
            blendStart[i] = float(view.splitFar - settings.shadow.blend * (view.splitFar - view.splitNear));
        }
        m_gl->glUniform4fv(p.techniqueUniform("uCascadeFar"), 1, &far[0]);
        m_gl->glUniform4fv(p.techniqueUniform("uCascadeBlendStart"), 1, &blendStart[0]);
        // Cascades are slices of the view depth of the camera they were fitted to.
        const CameraFrame& fitted = views.camera;
        const glm::dvec3 forward = -glm::dvec3(fitted.view[0][2], fitted.view[1][2], fitted.view[2][2]);
        p.program.set(p.techniqueUniform("uViewForward"), glm::vec3(forward));
        p.program.set(p.techniqueUniform("uViewOrigin"), glm::vec3(fitted.position - camera.position));
    }
}

void LitPass::setFrameUniforms(Program& p, const CameraFrame& camera, const LightFrame& light, const Settings& settings,
                               const ShadowMap* map, bool readsRange, const DepthRangePass* depthRange)
{
    p.program.bind();
    p.program.set(p.diffuse, int(kDiffuseUnit));
    // Camera-relative: differences of large coordinates are taken in double here, not in float
    // on the GPU.
    p.program.set(p.lightPosition, glm::vec3(light.position - camera.position));
    p.program.set(p.lightDirection, glm::vec3(light.direction));
    if (settings.light.type == LightType::Spot) {
        const double half = glm::radians(settings.light.fov) * 0.5;
        p.program.set(p.techniqueUniform("uSpotCone"), glm::vec2(float(std::cos(half)), float(std::cos(half * (1.0 - settings.light.falloff)))));
    }
    // A variant compiled with DEPTH_SLICES compares in the slice's stored depth; any other in
    // conventional depth (one without lookups still takes one for a measurement).
    const glm::dmat4 slice = p.depthSlices ? m_sliceMatrix : glm::dmat4(1.0);
    p.shadowMatrix = slice * light.depthShadowMatrix;
    if (map == nullptr)
        return;
    // The bias as set: a bias in texels is scaled by each view's texel in the shader, one in
    // depth units by the slice the lookups compare in.
    const double depthUnit = settings.bias.space == BiasSpace::Depth ? slice[2][2] : 1.0;
    p.program.set(p.biasSlope, float(settings.bias.slope * depthUnit));
    p.program.set(p.biasMin, float(settings.bias.min * depthUnit));
    for (const TechniqueUniform& u : shadowTechnique(settings.filter.mode).uniforms(settings))
        p.program.set(p.techniqueUniform(u.name), u.value);
    p.program.set(p.shadowTexel, glm::vec2(1.0f / float(map->width()), 1.0f / float(map->height())));
    p.program.set(p.techniqueUniform("uShadowSlice"), map->slice().uniform());
    // One view's position is taken in the vertex stage, with the normal offset in world units
    // from its texel (at unit distance for a perspective light), the wider axis.
    p.program.set(p.normalOffset, float(settings.bias.normal * texelWorldSize(light.volume, map->size())));
    p.program.set(p.shadowWorld, glm::mat4(p.shadowMatrix));
    if (m_views == nullptr || m_views->frames.empty())
        throw RenderError(QStringLiteral("the light's views were not fitted before the lit pass"));
    setViewUniforms(p, camera, settings, *map, slice);
    const std::vector<ShadowSampler>& samplers = shadowTechnique(settings.filter.mode).samplers;
    for (std::size_t i = 0; i < samplers.size(); ++i) {
        const bool readsMoments = samplers[i] == ShadowSampler::Moments;
        p.program.set(readsMoments ? p.shadowMoments : samplers[i] == ShadowSampler::RawNearest ? p.shadowDepth : p.shadowMap,
                      int(kShadowUnit + GLuint(i)));
    }
    if (m_virtualMap && settings.shadow.virtualMap) {
        const VirtualMapUniforms& v = *m_virtualMap;
        if (v.levelOffsets.empty())
            throw RenderError(QStringLiteral("shadow.virtual's pages were not requested before the lit pass"));
        p.program.set(p.techniqueUniform("uVirtualLight"), v.light);
        p.program.set(p.techniqueUniform("uVirtualLevels"), v.levels);
        p.program.set(p.techniqueUniform("uVirtualLodBias"), v.lodBias);
        m_gl->glUniform2fv(p.techniqueUniform("uVirtualLevelOffset"), GLsizei(v.levelOffsets.size()), &v.levelOffsets[0][0]);
        m_gl->glUniform2iv(p.techniqueUniform("uVirtualWrap"), GLsizei(v.wraps.size()), &v.wraps[0][0]);
        p.program.set(p.techniqueUniform("uVirtualPoolSide"), v.poolSide);
        p.program.set(p.techniqueUniform("uVirtualTexel0"), v.finestTexel);
        p.program.set(p.techniqueUniform("uVirtualPageTable"), int(kPageTableUnit));
    }
    if (usesContactShadows(settings)) {
        p.program.set(p.techniqueUniform("uCameraDepths"), int(kContactUnit));
        p.program.set(p.techniqueUniform("uCameraViewProjection"), glm::mat4(camera.viewProjection * glm::translate(glm::dmat4(1.0), camera.position)));
        p.program.set(p.techniqueUniform("uCameraForward"), glm::vec3(-camera.view[0][2], -camera.view[1][2], -camera.view[2][2]));
        p.program.set(p.techniqueUniform("uContactLength"), float(settings.contact.length));
        p.program.set(p.techniqueUniform("uContactThickness"), float(settings.contact.thickness));
        p.program.set(p.techniqueUniform("uContactSteps"), settings.contact.steps);
    }
    if (readsRange) {
        p.program.set(p.depthRange, int(kShadowUnit + GLuint(samplers.size())));
        p.program.set(p.depthRangeLevels, depthRange->levels());
        std::vector<GLint> levels;
        for (int level = 0; level < depthRange->levels(); ++level) {
            const QPoint at = depthRange->levelOrigin(level);
            const QSize size = depthRange->levelSize(level);
            levels.insert(levels.end(), {at.x(), at.y(), size.width(), size.height()});
        }
        m_gl->glUniform4iv(p.techniqueUniform("uDepthRangeLevel"), depthRange->levels(), levels.data());
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

void LitPass::drawReachMask(const CameraFrame& camera, const QRect& pixels)
{
    if (!m_maskProgram) {
        m_maskProgram = std::make_unique<ShaderProgram>(m_gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), QStringList());
        m_maskMatrix = m_maskProgram->uniform("uLightModelViewProjection");
        m_maskVertexArray = makeVertexArray(m_gl);
        m_maskVertices = makeBuffer(m_gl);
        m_gl->glBindVertexArray(m_maskVertexArray.id());
        m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_maskVertices.id());
        labelGlObject(GlLabelKind::VertexArray, m_maskVertexArray.id(), QStringLiteral("shadow reach mask"));
        m_gl->glEnableVertexAttribArray(0);
        m_gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    }
    m_gl->glBindVertexArray(m_maskVertexArray.id());
    if (m_maskGeneration != m_reach->generation) {
        // Each polygon as a fan, relative to the first vertex so that float keeps the precision
        // of a scene far from the origin.
        std::vector<glm::vec3> triangles;
        m_maskOrigin = m_reach->mask.empty() || m_reach->mask.front().empty() ? glm::dvec3(0.0) : m_reach->mask.front().front();
        for (const convex::Polygon& polygon : m_reach->mask) {
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
                for (const glm::dvec3& corner : {polygon[0], polygon[k], polygon[k + 1]})
                    triangles.emplace_back(corner - m_maskOrigin);
            }
        }
        m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_maskVertices.id());
        m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(glm::vec3)), triangles.data(), GL_STATIC_DRAW);
        m_maskVertexCount = GLsizei(triangles.size());
        m_maskGeneration = m_reach->generation;
    }
    // Both faces, with no depth test: a pixel is marked when its ray passes through a piece of a
    // flat receiver's plane inside a box, or through a box in front of the near plane, which
    // holds for every surface point inside one.
    // Depth clamp: a box is not clipped at the camera's near or far plane either.
    PassState state;
    state.depthTest = false;
    state.depthWrite = false;
    state.depthClamp = true;
    applyPassState(m_gl, state);
    m_gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    m_gl->glStencilMask(0xff);
    m_gl->glEnable(GL_STENCIL_TEST);
    m_gl->glStencilFunc(GL_ALWAYS, 1, 0xff);
    m_gl->glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    m_gl->glEnable(GL_SCISSOR_TEST);
    m_gl->glScissor(pixels.x(), pixels.y(), pixels.width(), pixels.height());
    m_maskProgram->bind();
    m_maskProgram->set(m_maskMatrix, glm::mat4(camera.viewProjection * glm::translate(glm::dmat4(1.0), m_maskOrigin)));
    if (m_maskVertexCount > 0)
        m_gl->glDrawArrays(GL_TRIANGLES, 0, m_maskVertexCount);
    m_gl->glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
}

void LitPass::drawObjects(const Programs& programs, const GpuScene& scene, const CameraFrame& camera,
                          const std::vector<std::pair<double, std::size_t>>& order)
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
        if (cutout)
            p.program.set(p.alphaCutoff, item.alphaCutoff);
        m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        scene.draw(item);
    }
}

void LitPass::sortByReach(const GpuScene& scene, const CameraFrame& camera, bool shadows)
{
    const auto& items = scene.drawItems();
    const bool reachKnown = shadows && m_reach != nullptr && m_reach->objects.size() == items.size();
    // Nearest first, so the depth test rejects hidden pixels before they are shaded: on a
    // software rasteriser every shaded pixel costs, and the ground plane is behind everything.
    m_drawOrder.clear();
    for (std::size_t i = 0; i < items.size(); ++i) {
        const Bounds& bounds = items[i].bounds;
        if (isOutsideFrustum(camera.viewProjection, bounds, false))
            continue;
        const glm::dvec3 nearest = glm::clamp(camera.position, bounds.min, bounds.max);
        m_drawOrder.emplace_back(glm::length(nearest - camera.position), i);
    }
    std::sort(m_drawOrder.begin(), m_drawOrder.end());
    // Which receivers need a lookup: those the reach touches; those that straddle it only inside
    // its stencil mask, when a mask is worth drawing.
    m_lookupOrder.clear();
    m_maskedLookupOrder.clear();
    m_maskedPlainOrder.clear();
    m_plainOrder.clear();
    const bool mask = reachKnown && !m_reach->boxes.empty() && m_reach->partlyCount() > 0 && m_reach->screenShare <= kMaxMaskShare
        && boundTargetHasStencil();
    for (const auto& entry : m_drawOrder) {
        const Reach reach = reachKnown ? m_reach->objects[entry.second] : Reach::Inside;
        if (reach == Reach::Outside) {
            m_plainOrder.push_back(entry);
        } else if (reach == Reach::Partly && mask) {
            m_maskedLookupOrder.push_back(entry);
            m_maskedPlainOrder.push_back(entry);
        } else {
            m_lookupOrder.push_back(entry);
        }
    }
    m_reachUse = ReachUse{int(m_lookupOrder.size() + m_maskedLookupOrder.size()), int(m_plainOrder.size() + m_maskedPlainOrder.size()), mask};
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

QRect LitPass::reachPixels(const glm::dvec4& r, QSize size)
{
    // A pixel of margin for rounding.
    const int x0 = std::max(int(std::floor((r.x + 1.0) * 0.5 * size.width())) - 1, 0);
    const int y0 = std::max(int(std::floor((r.y + 1.0) * 0.5 * size.height())) - 1, 0);
    const int x1 = std::min(int(std::ceil((r.z + 1.0) * 0.5 * size.width())) + 1, size.width());
    const int y1 = std::min(int(std::ceil((r.w + 1.0) * 0.5 * size.height())) + 1, size.height());
    return QRect(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
}

void LitPass::bindShadowTextures(const Settings& settings, const ShadowMap& map, const MomentsMap* moments, const DepthRangePass* depthRange)
{
    // Each sampler the technique's row asks for reads the map on a unit of its own.
    const std::vector<ShadowSampler>& samplers = shadowTechnique(settings.filter.mode).samplers;
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

void LitPass::unbindShadowTextures(const Settings& settings, bool readsRange)
{
    for (std::size_t i = 0; i < shadowTechnique(settings.filter.mode).samplers.size() + (readsRange ? 1 : 0); ++i) {
        m_gl->glActiveTexture(GL_TEXTURE0 + kShadowUnit + GLuint(i));
        m_gl->glBindTexture(GL_TEXTURE_2D, 0);
        m_gl->glBindSampler(kShadowUnit + GLuint(i), 0);
    }
    m_gl->glActiveTexture(GL_TEXTURE0);
}

void LitPass::drawMaskedOrder(const Programs& p, const GpuScene& scene, const CameraFrame& camera,
                              const std::vector<std::pair<double, std::size_t>>& everywhere,
                              const std::vector<std::pair<double, std::size_t>>& masked, GLenum stencilFunc, const std::vector<QRect>* scissors)
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
void checkInputs(const Settings& settings, const ShadowMap* shadowMap, bool range, const DepthRangePass* depthRange, const MomentsMap* moments,
                 GLuint contactDepth)
{
    if (shadowMap != nullptr && isMomentTechnique(settings.filter.mode) && (moments == nullptr || moments->size() != shadowMap->size()))
        throw RenderError(QStringLiteral("filter.mode=%1 reads a moments map, which was not rendered").arg(toString(settings.filter.mode)));
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

int LitPass::render(const GpuScene& scene, const CameraFrame& camera, const LightFrame& light, const Settings& settings,
                    const ShadowMap* map, const RenderTarget& target, bool measure, const DepthRangePass* depthRange,
                    const MomentsMap* moments)
{
    const bool shadows = settings.shadow.enabled && map != nullptr;
    const bool readsRange = usesDepthRange(settings) && map != nullptr;
    m_floorsLeftOutFor = settings.bias.skipFloors ? &light : nullptr;
    const bool contact = shadows && usesContactShadows(settings);
    checkInputs(settings, shadows ? map : nullptr, readsRange, depthRange, moments, contact ? m_contactDepth : GLuint(1));

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    sortByReach(scene, camera, shadows);
    PassState state;
    state.viewport = QRect(QPoint(0, 0), target.size);
    state.depthTest = true;
    state.cullFace = GL_BACK;
    applyPassState(m_gl, state);
    clearTarget(measure);
    // The lookups' draws stay inside the reach's rectangle on screen, so the rasteriser skips
    // the rest of the frame for them.
    std::vector<QRect> lookupRects;
    if (m_reachUse.masked) {
        drawReachMask(camera, reachPixels(m_reach->screenRect, target.size));
        for (const glm::dvec4& rect : m_reach->screenRects)
            lookupRects.push_back(reachPixels(rect, target.size));
        applyPassState(m_gl, state);
    }
    if (shadows)
        bindShadowTextures(settings, *map, moments, readsRange ? depthRange : nullptr);
    if (contact)
        bindUnit(m_gl, kContactUnit, m_contactDepth);
    const bool pageTable = shadows && settings.shadow.virtualMap && m_virtualMap != nullptr;
    if (pageTable)
        bindUnit(m_gl, kPageTableUnit, m_virtualMap->pageTable);
    const ShadowMap* shadowMap = shadows ? map : nullptr;
    m_sliceMatrix = shadows ? map->slice().matrix() : glm::dmat4(1.0);
    Variant variant{.measure = measure, .reversedDepth = light.reversedDepth, .warped = light.volume.warped};
    if (m_views) {
        for (const LightFrame& frame : m_views->frames)
            variant.warped = variant.warped || frame.volume.warped;
    }
    if (!m_lookupOrder.empty() || !m_maskedLookupOrder.empty()) {
        const Programs lookup = programsFor(scene, settings, variant);
        for (Program* p : {lookup.plain, lookup.cutout}) {
            if (p)
                setFrameUniforms(*p, camera, light, settings, shadowMap, readsRange, depthRange);
        }
        if (m_counting)
            m_lookupSamples.begin();
        drawMaskedOrder(lookup, scene, camera, m_lookupOrder, m_maskedLookupOrder, GL_EQUAL, &lookupRects);
        if (m_counting)
            m_lookupSamples.end();
    }
    if (!m_plainOrder.empty() || !m_maskedPlainOrder.empty()) {
        variant.outOfReach = true;
        const Programs plain = programsFor(scene, settings, variant);
        for (Program* p : {plain.plain, plain.cutout}) {
            if (p)
                setFrameUniforms(*p, camera, light, settings, shadowMap, readsRange, depthRange);
        }
        if (m_counting)
            m_plainSamples.begin();
        drawMaskedOrder(plain, scene, camera, m_plainOrder, m_maskedPlainOrder, GL_NOTEQUAL, nullptr);
        if (m_counting)
            m_plainSamples.end();
    }
    m_fragments = {.lookup = std::max<std::int64_t>(m_lookupSamples.result(), 0), .plain = std::max<std::int64_t>(m_plainSamples.result(), 0)};
    const int draws = int(m_lookupOrder.size() + m_maskedLookupOrder.size() + m_plainOrder.size() + m_maskedPlainOrder.size());

    m_gl->glBindVertexArray(0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    if (shadows)
        unbindShadowTextures(settings, readsRange);
    for (const auto& [unit, used] : {std::pair{kContactUnit, contact}, std::pair{kPageTableUnit, pageTable}}) {
        if (used)
            bindUnit(m_gl, unit, 0, GL_TEXTURE0);
    }
    m_gl->glDisable(GL_CULL_FACE);
    return draws;
}

} // namespace shadowlab
