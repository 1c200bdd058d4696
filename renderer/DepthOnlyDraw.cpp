#include "DepthOnlyDraw.h"

#include "LightMath.h"

namespace shadowlab {

DepthOnlyDraw::Variant::Variant(GlFunctions* gl, const QStringList& defines)
    : program(gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), defines),
      mvp(program.uniform("uLightModelViewProjection")),
      alphaCutoff(program.uniform("uAlphaCutoff"))
{
}

DepthOnlyDraw::DepthOnlyDraw(GlFunctions* gl, bool fullResolutionMask) : m_gl(gl), m_fullResolutionMask(fullResolutionMask), m_plain(gl, {}) {}

int DepthOnlyDraw::draw(const GpuScene& scene, const Items& items)
{
    m_gl->glActiveTexture(GL_TEXTURE0);
    Variant* bound = nullptr;
    int draws = 0;
    for (const DrawItem& item : scene.drawItems()) {
        if ((items.castersOnly && !item.castsShadow) || !drawsItem(items.casters, item) || (items.light && shadowsNothing(item, *items.light))
            || isOutsideFrustum(items.culling, item.bounds, items.clampDepth))
            continue;
        const bool cutout = items.cutouts && item.alphaCutoff > 0.0f;
        if (cutout && !m_cutout) {
            QStringList defines{QStringLiteral("ALPHA_CUTOUT")};
            if (m_fullResolutionMask)
                defines << QStringLiteral("CUTOUT_FULL_RESOLUTION");
            m_cutout = std::make_unique<Variant>(m_gl, defines);
        }
        Variant& v = cutout ? *m_cutout : m_plain;
        if (&v != bound) {
            v.program.bind();
            bound = &v;
        }
        v.program.set(v.mvp, glm::mat4(items.viewProjection * item.model));
        if (cutout) {
            v.program.set(v.alphaCutoff, item.alphaCutoff);
            m_gl->glBindTexture(GL_TEXTURE_2D, scene.texture(item));
        }
        scene.draw(item, false);
        ++draws;
    }
    m_gl->glBindTexture(GL_TEXTURE_2D, 0);
    m_gl->glBindVertexArray(0);
    return draws;
}

} // namespace shadowlab
