#include "ReachDraws.h"

#include "PassState.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Above this share of the frame a mask saves less than drawing the straddling receivers twice
// costs (both halves still run every vertex and set up every triangle).
constexpr double kMaxMaskShare = 0.6;

// A rectangle of the reach on screen (ShadowReach::screenRect or one of screenRects) in pixels
// of a target of `size`, with a pixel of margin for rounding.
QRect reachPixels(const glm::dvec4& r, QSize size)
{
    const int x0 = std::max(int(std::floor((r.x + 1.0) * 0.5 * size.width())) - 1, 0);
    const int y0 = std::max(int(std::floor((r.y + 1.0) * 0.5 * size.height())) - 1, 0);
    const int x1 = std::min(int(std::ceil((r.z + 1.0) * 0.5 * size.width())) + 1, size.width());
    const int y1 = std::min(int(std::ceil((r.w + 1.0) * 0.5 * size.height())) + 1, size.height());
    return QRect(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
}

} // namespace

ReachDraws::ReachDraws(GlFunctions* gl) : m_gl(gl) {}

void ReachDraws::sort(const GpuScene& scene, const CameraFrame& camera, bool shadows, const ShadowReach* reach, bool stencil)
{
    const auto& items = scene.drawItems();
    m_reach = reach;
    const bool reachKnown = shadows && reach != nullptr && reach->objects.size() == items.size();
    // Nearest first, so the depth test rejects hidden pixels before they are shaded: on a
    // software rasteriser every shaded pixel costs, and the ground plane is behind everything.
    m_order.clear();
    for (std::size_t i = 0; i < items.size(); ++i) {
        const Bounds& bounds = items[i].bounds;
        if (isOutsideFrustum(camera.viewProjection, bounds, false))
            continue;
        const glm::dvec3 nearest = glm::clamp(camera.position, bounds.min, bounds.max);
        m_order.emplace_back(glm::length(nearest - camera.position), i);
    }
    std::sort(m_order.begin(), m_order.end());
    // Which receivers need a lookup: those the reach touches; those that straddle it only inside
    // its stencil mask, when a mask is worth drawing.
    m_lookup.clear();
    m_maskedLookup.clear();
    m_maskedPlain.clear();
    m_plain.clear();
    const bool mask = reachKnown && !reach->boxes.empty() && reach->partlyCount() > 0 && reach->screenShare <= kMaxMaskShare && stencil;
    for (const auto& entry : m_order) {
        const Reach where = reachKnown ? reach->objects[entry.second] : Reach::Inside;
        if (where == Reach::Outside) {
            m_plain.push_back(entry);
        } else if (where == Reach::Partly && mask) {
            m_maskedLookup.push_back(entry);
            m_maskedPlain.push_back(entry);
        } else {
            m_lookup.push_back(entry);
        }
    }
    m_use = Use{int(m_lookup.size() + m_maskedLookup.size()), int(m_plain.size() + m_maskedPlain.size()), mask};
}

void ReachDraws::uploadMask()
{
    if (!m_program) {
        m_program = std::make_unique<ShaderProgram>(m_gl, QStringLiteral("depth.vert"), QStringLiteral("depth.frag"), QStringList());
        m_matrix = m_program->uniform("uLightModelViewProjection");
        m_vertexArray = makeVertexArray(m_gl);
        m_vertices = makeBuffer(m_gl);
        m_gl->glBindVertexArray(m_vertexArray.id());
        m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
        labelGlObject(GlLabelKind::VertexArray, m_vertexArray.id(), QStringLiteral("shadow reach mask"));
        m_gl->glEnableVertexAttribArray(0);
        m_gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    }
    m_gl->glBindVertexArray(m_vertexArray.id());
    if (m_generation == m_reach->generation)
        return;
    // Each polygon as a fan, relative to the first vertex so that float keeps the precision of a
    // scene far from the origin.
    std::vector<glm::vec3> triangles;
    m_origin = m_reach->mask.empty() || m_reach->mask.front().empty() ? glm::dvec3(0.0) : m_reach->mask.front().front();
    for (const convex::Polygon& polygon : m_reach->mask) {
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            for (const glm::dvec3& corner : {polygon[0], polygon[k], polygon[k + 1]})
                triangles.emplace_back(corner - m_origin);
        }
    }
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
    m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(glm::vec3)), triangles.data(), GL_STATIC_DRAW);
    m_vertexCount = GLsizei(triangles.size());
    m_generation = m_reach->generation;
}

std::vector<QRect> ReachDraws::drawMask(const CameraFrame& camera, QSize targetSize)
{
    if (!m_use.masked)
        return {};
    uploadMask();
    const QRect pixels = reachPixels(m_reach->screenRect, targetSize);
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
    m_program->bind();
    m_program->set(m_matrix, glm::mat4(camera.viewProjection * glm::translate(glm::dmat4(1.0), m_origin)));
    if (m_vertexCount > 0)
        m_gl->glDrawArrays(GL_TRIANGLES, 0, m_vertexCount);
    m_gl->glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    std::vector<QRect> scissors;
    for (const glm::dvec4& rect : m_reach->screenRects)
        scissors.push_back(reachPixels(rect, targetSize));
    return scissors;
}

} // namespace shadowlab
