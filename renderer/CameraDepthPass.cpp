#include "CameraDepthPass.h"

#include "PassState.h"
#include "RenderError.h"

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

namespace {

GlTexture makeTarget(GlFunctions* gl, QSize size, GLint format, GLenum layout, GLenum type, const QString& label)
{
    GlTexture texture = makeTexture(gl);
    gl->glBindTexture(GL_TEXTURE_2D, texture.id());
    gl->glTexImage2D(GL_TEXTURE_2D, 0, format, size.width(), size.height(), 0, layout, type, nullptr);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    labelGlObject(GlLabelKind::Texture, texture.id(), label);
    gl->glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

} // namespace

CameraDepthPass::Variant::Variant(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("cameradepth.vert"), QStringLiteral("cameradepth.frag"), defines),
      mvp(program.uniform("uModelViewProjection")),
      model(program.uniform("uModel")),
      forward(program.uniform("uCameraForward")),
      alphaCutoff(program.uniform("uAlphaCutoff"))
{
}

CameraDepthPass::CameraDepthPass(GlFunctions* gl) : m_gl(gl), m_plain(gl, {}) {}

void CameraDepthPass::allocate(QSize size)
{
    m_framebuffer.reset();
    const QString dimensions = QStringLiteral("%1 x %2").arg(size.width()).arg(size.height());
    m_texture = makeTarget(m_gl, size, GL_RG32F, GL_RG, GL_FLOAT, QStringLiteral("camera view depth of casters, front and back faces, ") + dimensions);
    m_depth = makeTarget(m_gl, size, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, QStringLiteral("camera depth prepass depth, ") + dimensions);
    m_framebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_texture.id(), 0);
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
    const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    labelGlObject(GlLabelKind::Framebuffer, m_framebuffer.id(), QStringLiteral("camera depth prepass"));
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the %1 camera depth framebuffer for contact shadows is incomplete (status 0x%2); "
                                         "set contact.enabled=false")
                              .arg(dimensions).arg(status, 0, 16));
    m_size = size;
}

int CameraDepthPass::draw(const GpuScene& scene, const CameraFrame& camera, GLenum culled, bool cutouts)
{
    PassState state;
    state.viewport = QRect(QPoint(0, 0), m_size);
    state.depthTest = true;
    state.cullFace = culled;
    applyPassState(m_gl, state);
    // Each pass writes only its own channel (applyPassState opened the colour mask).
    m_gl->glColorMask(culled == GL_BACK, culled == GL_FRONT, GL_FALSE, GL_FALSE);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    const glm::dmat4 toCamera = glm::translate(glm::dmat4(1.0), -camera.position);
    const glm::vec3 forward(-camera.view[0][2], -camera.view[1][2], -camera.view[2][2]);
    Variant* bound = nullptr;
    m_gl->glActiveTexture(GL_TEXTURE0);
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadow || isOutsideFrustum(camera.viewProjection, item.bounds, false))
            continue;
        const bool cutout = cutouts && item.alphaCutoff > 0.0f;
        if (cutout && !m_cutout)
            m_cutout = std::make_unique<Variant>(m_gl, QStringList{QStringLiteral("ALPHA_CUTOUT")});
        Variant& v = cutout ? *m_cutout : m_plain;
        if (&v != bound) {
            v.program.bind();
            v.program.set(v.forward, forward);
            bound = &v;
        }
        v.program.set(v.mvp, glm::mat4(camera.viewProjection * item.model));
        v.program.set(v.model, glm::mat4(toCamera * item.model));
        if (cutout) {
            v.program.set(v.alphaCutoff, item.alphaCutoff);
            m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        }
        scene.draw(item, false);
        ++draws;
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return draws;
}

int CameraDepthPass::ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera, QSize size, bool cutouts)
{
    const Key key{sceneGeneration, camera.viewProjection, size, cutouts};
    if (m_key == key)
        return 0;
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    if (!m_texture || m_size != size)
        allocate(size);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    m_gl->glClearColor(kNoCasterDepth, kNoCasterDepth, 0.0f, 0.0f);   // both channels: no caster
    m_gl->glClear(GL_COLOR_BUFFER_BIT);
    const int draws = draw(scene, camera, GL_BACK, cutouts) + draw(scene, camera, GL_FRONT, cutouts);
    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    m_key = key;
    return draws;
}

} // namespace shadowlab
