#include "LightGizmoPass.h"

#include "PassState.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <array>
#include <cstddef>

namespace shadowlab {

namespace {

const glm::vec4 kLightColor{1.0f, 0.84f, 0.25f, 1.0f};
const glm::vec4 kVolumeColor{1.0f, 0.72f, 0.2f, 0.8f};
const glm::vec4 kFrozenColor{0.45f, 0.85f, 1.0f, 0.9f};

// The world corners of the unit cube of a clip space: corner i has x, y, z at +1 where bit 0,
// 1, 2 of i is set.
std::array<glm::dvec3, 8> clipCorners(const glm::dmat4& viewProjection)
{
    const glm::dmat4 toWorld = glm::inverse(viewProjection);
    std::array<glm::dvec3, 8> corner;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p = toWorld * glm::dvec4(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0, 1.0);
        corner[std::size_t(i)] = glm::dvec3(p) / p.w;
    }
    return corner;
}
constexpr float kHiddenAlpha = 0.22f;

// The star's size is a fixed fraction of its distance to the camera, so it reads the same
// at any zoom.
constexpr double kStarScale = 0.035;

} // namespace

LightGizmoPass::LightGizmoPass(GlFunctions* gl)
    : m_gl(gl), m_program(gl, QStringLiteral("gizmo.vert"), QStringLiteral("gizmo.frag"), {}),
      m_viewProjection(m_program.uniform("uViewProjection")), m_vertexArray(makeVertexArray(gl)), m_vertices(makeBuffer(gl))
{
    m_gl->glBindVertexArray(m_vertexArray.id());
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
    m_gl->glEnableVertexAttribArray(0);
    m_gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                                reinterpret_cast<const void*>(offsetof(LineVertex, position)));
    m_gl->glEnableVertexAttribArray(1);
    m_gl->glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                                reinterpret_cast<const void*>(offsetof(LineVertex, color)));
    labelGlObject(GlLabelKind::VertexArray, m_vertexArray.id(), QStringLiteral("light gizmo"));
    labelGlObject(GlLabelKind::Buffer, m_vertices.id(), QStringLiteral("light gizmo: lines"));
    m_gl->glBindVertexArray(0);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void LightGizmoPass::addLine(const glm::dvec3& a, const glm::dvec3& b, const glm::vec4& color)
{
    m_lines.push_back({glm::vec3(a), color});
    m_lines.push_back({glm::vec3(b), color});
}

void LightGizmoPass::addBox(const std::array<glm::dvec3, 8>& corner, const glm::vec4& color)
{
    for (int i = 0; i < 8; ++i) {
        for (int bit : {1, 2, 4}) {
            if (!(i & bit))
                addLine(corner[std::size_t(i)], corner[std::size_t(i | bit)], color);
        }
    }
}

void LightGizmoPass::render(const LightFrame& light, const CameraFrame& camera, bool showVolume, const RenderTarget& target,
                            const CameraFrame* frozen)
{
    if (target.size.isEmpty())
        return;
    m_lines.clear();

    const double star = kStarScale * glm::length(camera.position - light.position);
    const std::array<glm::dvec3, 3> axes{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
    for (const glm::dvec3& axis : axes)
        addLine(light.position - axis * star, light.position + axis * star, kLightColor);
    // The direction it shines, as long as the star is wide, so a directional light shows its way.
    addLine(light.position, light.position + light.direction * (star * 4.0), kLightColor);

    if (showVolume) {
        // The volume is the unit cube of the light's clip space taken back to the world.
        const std::array<glm::dvec3, 8> corner = clipCorners(light.viewProjection);
        addBox(corner, kVolumeColor);
        // Rays from the light to the near corners make a perspective volume read as a cone.
        if (light.perspective) {
            for (int i = 0; i < 4; ++i)
                addLine(light.position, corner[std::size_t(i)], kVolumeColor * glm::vec4(1, 1, 1, 0.5f));
        }
    }

    if (frozen) {
        // The frozen camera's frustum, its eye joined to the near corners.
        const std::array<glm::dvec3, 8> corner = clipCorners(frozen->viewProjection);
        addBox(corner, kFrozenColor);
        for (int i = 0; i < 4; ++i)
            addLine(frozen->position, corner[std::size_t(i)], kFrozenColor);
    }

    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
    m_gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m_lines.size() * sizeof(LineVertex)), m_lines.data(), GL_STREAM_DRAW);
    m_gl->glBindBuffer(GL_ARRAY_BUFFER, 0);

    m_program.bind();
    m_program.set(m_viewProjection, glm::mat4(camera.viewProjection));
    m_gl->glBindVertexArray(m_vertexArray.id());

    // Hidden parts first at a fixed faint alpha, then the visible ones at their own. The
    // target's alpha stays 1: a widget's framebuffer is composited as premultiplied colour.
    PassState hidden;
    hidden.viewport = QRect(QPoint(0, 0), target.size);
    hidden.depthTest = true;
    hidden.depthWrite = false;
    hidden.depthFunc = GL_GREATER;
    hidden.blend = true;
    hidden.blendSourceRgb = GL_CONSTANT_ALPHA;
    hidden.blendDestinationRgb = GL_ONE_MINUS_CONSTANT_ALPHA;
    hidden.blendSourceAlpha = GL_ZERO;
    hidden.blendDestinationAlpha = GL_ONE;
    hidden.blendConstantAlpha = kHiddenAlpha;
    applyPassState(m_gl, hidden);
    m_gl->glDrawArrays(GL_LINES, 0, GLsizei(m_lines.size()));
    PassState visible = hidden;
    visible.depthFunc = GL_LEQUAL;
    visible.blendSourceRgb = GL_SRC_ALPHA;
    visible.blendDestinationRgb = GL_ONE_MINUS_SRC_ALPHA;
    applyPassState(m_gl, visible);
    m_gl->glDrawArrays(GL_LINES, 0, GLsizei(m_lines.size()));

    m_gl->glBindVertexArray(0);
    applyPassState(m_gl, PassState{});
}

} // namespace shadowlab
