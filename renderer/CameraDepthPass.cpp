#include "CameraDepthPass.h"

#include "PassState.h"
#include "RenderError.h"

namespace shadowlab {

CameraDepthPass::CameraDepthPass(GlFunctions* gl)
    : m_gl(gl), m_program(gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), {}),
      m_mvpLocation(m_program.uniform("uLightModelViewProjection"))
{
}

void CameraDepthPass::allocate(Layer& layer, QSize size, const char* faces)
{
    layer.framebuffer.reset();
    layer.texture = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, layer.texture.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, size.width(), size.height(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    labelGlObject(GlLabelKind::Texture, layer.texture.id(), QStringLiteral("camera depth of %1 faces %2 x %3").arg(QLatin1String(faces)).arg(size.width()).arg(size.height()));
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    layer.framebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, layer.framebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, layer.texture.id(), 0);
    m_gl->glDrawBuffer(GL_NONE);
    m_gl->glReadBuffer(GL_NONE);
    const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    labelGlObject(GlLabelKind::Framebuffer, layer.framebuffer.id(), QStringLiteral("camera depth pass, %1 faces").arg(QLatin1String(faces)));
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the %1 x %2 camera depth framebuffer for contact shadows is incomplete (status 0x%3); "
                                         "set contact.enabled=false")
                              .arg(size.width()).arg(size.height()).arg(status, 0, 16));
}

int CameraDepthPass::draw(const Layer& layer, const GpuScene& scene, const CameraFrame& camera, GLenum culled)
{
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, layer.framebuffer.id());
    PassState state;
    state.viewport = QRect(QPoint(0, 0), m_size);
    state.depthTest = true;
    state.cullFace = culled;
    applyPassState(m_gl, state);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadow || isOutsideFrustum(camera.viewProjection, item.bounds, false))
            continue;
        m_program.set(m_mvpLocation, glm::mat4(camera.viewProjection * item.model));
        scene.draw(item, false);
        ++draws;
    }
    return draws;
}

int CameraDepthPass::ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera, QSize size)
{
    const Key key{sceneGeneration, camera.viewProjection, size};
    if (m_key == key)
        return 0;
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    if (!m_front.texture || m_size != size) {
        allocate(m_front, size, "front");
        allocate(m_back, size, "back");
        m_size = size;
    }
    m_program.bind();
    const int draws = draw(m_front, scene, camera, GL_BACK) + draw(m_back, scene, camera, GL_FRONT);
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    m_key = key;
    return draws;
}

} // namespace shadowlab
