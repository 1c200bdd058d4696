#include "DepthPass.h"

#include <QOpenGLContext>

// Core in GL 4.5; the 3.3 headers may not name them.
#ifndef GL_NEGATIVE_ONE_TO_ONE
#define GL_NEGATIVE_ONE_TO_ONE 0x935E
#endif
#ifndef GL_ZERO_TO_ONE
#define GL_ZERO_TO_ONE 0x935F
#endif

namespace shadowlab {

DepthPass::DepthPass(GlFunctions* gl)
    : m_gl(gl), m_program(gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), {}),
      m_mvpLocation(m_program.uniform("uLightModelViewProjection"))
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    const QSurfaceFormat format = context ? context->format() : QSurfaceFormat();
    const bool core45 = format.version() >= qMakePair(4, 5);
    if (context && (core45 || context->hasExtension(QByteArrayLiteral("GL_ARB_clip_control"))))
        m_clipControl = reinterpret_cast<decltype(m_clipControl)>(context->getProcAddress("glClipControl"));
}

void DepthPass::clear(const ShadowMap& map, bool reversedDepth)
{
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    m_gl->glViewport(0, 0, map.size(), map.size());
    resetPassState(m_gl);
    m_gl->glDepthMask(GL_TRUE);
    m_gl->glClearDepth(reversedDepth ? 0.0 : 1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    m_gl->glClearDepth(1.0);
}

int DepthPass::render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, const ShadowMap& map)
{
    const bool reversed = light.reversedDepth;   // the Renderer asks only when supportsReversedDepth()
    clear(map, reversed);
    m_gl->glEnable(GL_DEPTH_TEST);
    if (reversed)
        m_clipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    m_gl->glDepthFunc(reversed ? GL_GREATER : GL_LESS);

    // The fitted near plane is the nearest receiver, not the nearest caster: casters between
    // the light and the near plane still cast, so clamp their depth to the near plane instead
    // of clipping them away (a perspective light's side planes still clip what is behind it).
    const bool clampDepth = true;
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
        // Offsets push depth away from the light, which is downward with reversed depth.
        const float sign = reversed ? -1.0f : 1.0f;
        m_gl->glPolygonOffset(sign * float(bias.polygonFactor), sign * float(bias.polygonUnits));
    }

    m_program.bind();
    int draws = 0;
    const auto& objects = scene.scene().objects;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& object = objects[i];
        if (!object.castsShadow || isOutsideFrustum(light.viewProjection, scene.objectBounds(i), clampDepth))
            continue;
        m_program.set(m_mvpLocation, glm::mat4(light.depthViewProjection * object.model));
        scene.draw(object);
        ++draws;
    }

    m_gl->glBindVertexArray(0);
    if (offset)
        m_gl->glDisable(GL_POLYGON_OFFSET_FILL);
    m_gl->glDisable(GL_CULL_FACE);
    m_gl->glCullFace(GL_BACK);
    m_gl->glDisable(GL_DEPTH_CLAMP);
    if (reversed) {
        m_clipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        m_gl->glDepthFunc(GL_LESS);
    }
    return draws;
}

} // namespace shadowlab
