#pragma once

#include "LightMath.h"
#include "RenderTarget.h"
#include "ShaderProgram.h"

#include <glm/vec4.hpp>

#include <array>
#include <vector>

namespace shadowlab {

// Draws the light into the lit scene: a small star at its position, a line to its target and,
// optionally, its volume (the shadow map's frustum or box) as a wireframe. Runs after the lit
// pass on the same target, reusing its depth buffer so the scene hides what is behind it;
// hidden edges are drawn again faintly so the volume reads as a whole.
class LightGizmoPass {
public:
    explicit LightGizmoPass(GlFunctions* gl);

    // `frozen`: a camera the light was fitted to in place of `camera` (View > Freeze Shadow
    // Frustum), drawn as its frustum.
    void render(const LightFrame& light, const CameraFrame& camera, bool showVolume, const RenderTarget& target,
                const CameraFrame* frozen = nullptr);

private:
    struct LineVertex {
        glm::vec3 position;
        glm::vec4 color;
    };

    void addLine(const glm::dvec3& a, const glm::dvec3& b, const glm::vec4& color);
    // The 12 edges between corners that differ in one bit (clipCorners()' order).
    void addBox(const std::array<glm::dvec3, 8>& corner, const glm::vec4& color);

    GlFunctions* m_gl;
    ShaderProgram m_program;
    GLint m_viewProjection;
    GlVertexArray m_vertexArray;
    GlBuffer m_vertices;
    std::vector<LineVertex> m_lines;    // rebuilt per frame: a few dozen vertices
};

} // namespace shadowlab
