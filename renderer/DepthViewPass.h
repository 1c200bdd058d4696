#pragma once

#include "LightMath.h"
#include "RenderTarget.h"
#include "ShaderProgram.h"

#include <QRectF>

#include <memory>

namespace shadowlab {

// Draws a shadow map as a grey image: raw depth for an ortho light, linearised between near
// and far for a perspective one. Usable from any context that shares the map's texture, so
// the depth-map widget samples the renderer's map directly.
class DepthViewPass {
public:
    explicit DepthViewPass(GlFunctions* gl);

    // `visible` is the part of the map shown, in map coordinates ([0, 1]^2 is the whole map,
    // y up); it is stretched over the whole target.
    void render(GLuint depthTexture, const LightFrame& light, const RenderTarget& target,
                const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0));

private:
    struct Program {
        Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint depth, nearPlane, farPlane, uvOffset, uvScale;
    };

    GlFunctions* m_gl;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlSampler m_sampler;
    Program m_raw;
    std::unique_ptr<Program> m_linear;  // compiled when a perspective light is first shown
};

} // namespace shadowlab
