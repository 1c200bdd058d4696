#include "DepthPass.h"

namespace shadowlab {

DepthPass::DepthPass(GlFunctions* gl)
    : m_gl(gl), m_program(gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), {}),
      m_mvpLocation(m_program.uniform("uLightModelViewProjection"))
{
}

int DepthPass::render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, const ShadowMap& map)
{
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    m_gl->glViewport(0, 0, map.size(), map.size());
    m_gl->glEnable(GL_DEPTH_TEST);
    m_gl->glDepthFunc(GL_LESS);
    m_gl->glDepthMask(GL_TRUE);
    m_gl->glClearDepth(1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);

    // An ortho light is a direction: casters between the light's position and its near plane
    // still cast, so clamp their depth to 0 instead of clipping them away.
    const bool clampDepth = !light.perspective;
    if (clampDepth)
        m_gl->glEnable(GL_DEPTH_CLAMP);
    if (bias.cullFront) {
        m_gl->glEnable(GL_CULL_FACE);
        m_gl->glCullFace(GL_FRONT);
    } else {
        m_gl->glDisable(GL_CULL_FACE);
    }
    const bool offset = bias.polygonFactor != 0.0 || bias.polygonUnits != 0.0;
    if (offset) {
        m_gl->glEnable(GL_POLYGON_OFFSET_FILL);
        m_gl->glPolygonOffset(float(bias.polygonFactor), float(bias.polygonUnits));
    }

    m_program.bind();
    int draws = 0;
    const auto& objects = scene.scene().objects;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& object = objects[i];
        if (!object.castsShadow || isOutsideFrustum(light.viewProjection, scene.objectBounds(i), clampDepth))
            continue;
        m_program.set(m_mvpLocation, glm::mat4(light.viewProjection * object.model));
        scene.draw(object);
        ++draws;
    }

    m_gl->glBindVertexArray(0);
    if (offset)
        m_gl->glDisable(GL_POLYGON_OFFSET_FILL);
    m_gl->glDisable(GL_CULL_FACE);
    m_gl->glCullFace(GL_BACK);
    if (clampDepth)
        m_gl->glDisable(GL_DEPTH_CLAMP);
    return draws;
}

} // namespace shadowlab
