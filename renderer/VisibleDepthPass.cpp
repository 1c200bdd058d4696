#include "VisibleDepthPass.h"

#include "PassState.h"
#include "RenderError.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

VisibleDepthPass::VisibleDepthPass(GlFunctions* gl) : m_gl(gl), m_draw(gl, false) {}

void VisibleDepthPass::allocate(QSize size)
{
    m_framebuffer.reset();
    m_gl->glActiveTexture(GL_TEXTURE0);
    m_depth = makeTexture(m_gl);
    m_gl->glBindTexture(GL_TEXTURE_2D, m_depth.id());
    m_gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, size.width(), size.height(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    const QString dimensions = QStringLiteral("%1 x %2").arg(size.width()).arg(size.height());
    labelGlObject(GlLabelKind::Texture, m_depth.id(), QStringLiteral("visible depth prepass, ") + dimensions);
    m_framebuffer = makeFramebuffer(m_gl);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
    m_gl->glDrawBuffer(GL_NONE);
    m_gl->glReadBuffer(GL_NONE);
    labelGlObject(GlLabelKind::Framebuffer, m_framebuffer.id(), QStringLiteral("visible depth prepass"));
    if (const GLenum status = m_gl->glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError(QStringLiteral("the %1 depth prepass for shadow.depth_fit=sdsm is incomplete (status 0x%2); "
                                         "set shadow.depth_fit=distance")
                              .arg(dimensions).arg(status, 0, 16));
    m_size = size;
}

int VisibleDepthPass::draw(const GpuScene& scene, const CameraFrame& camera)
{
    PassState state;
    state.viewport = QRect(QPoint(0, 0), m_size);
    state.depthTest = true;
    state.cullFace = GL_BACK;   // as the lit pass draws
    applyPassState(m_gl, state);
    m_gl->glClearDepth(1.0);
    m_gl->glClear(GL_DEPTH_BUFFER_BIT);
    const int draws = m_draw.draw(scene, {.viewProjection = camera.viewProjection, .culling = camera.viewProjection});
    applyPassState(m_gl, PassState{});
    return draws;
}

std::optional<VisibleDepthRange> VisibleDepthPass::ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera,
                                                          QSize frameSize, int* draws)
{
    const QSize size(std::max(frameSize.width(), 1), std::max(frameSize.height(), 1));
    const Key key{sceneGeneration, camera.viewProjection, size};
    if (draws)
        *draws = 0;
    if (m_key == key)
        return m_range;
    GLint previousDraw = 0, previousRead = 0;
    m_gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousDraw);
    m_gl->glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    const auto restore = [&] {
        m_gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousDraw));
        m_gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    };
    if (!m_depth || m_size != size) {
        try {
            allocate(size);
        } catch (...) {
            m_depth.reset();    // allocated again on the next frame
            restore();
            throw;
        }
    }
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    const int drawn = draw(scene, camera);
    if (draws)
        *draws = drawn;
    m_readback.resize(std::size_t(size.width()) * std::size_t(size.height()));
    m_gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    m_gl->glReadPixels(0, 0, size.width(), size.height(), GL_DEPTH_COMPONENT, GL_FLOAT, m_readback.data());
    restore();
    // Window depth d in [0, 1] of GL's perspective back to the distance along the view.
    float low = 1.0f, high = 0.0f;
    for (const float d : m_readback) {
        if (d < 1.0f) {
            low = std::min(low, d);
            high = std::max(high, d);
        }
    }
    m_range.reset();
    if (low <= high) {
        const double n = camera.nearPlane, f = camera.farPlane;
        const auto viewDepth = [&](double d) { return 2.0 * n * f / (f + n - (2.0 * d - 1.0) * (f - n)); };
        m_range = VisibleDepthRange{viewDepth(low), viewDepth(high)};
    }
    m_key = key;
    return m_range;
}

} // namespace shadowlab
