#pragma once

#include "LightMath.h"
#include "RenderTarget.h"
#include "Settings.h"
#include "ShaderProgram.h"

#include <QRectF>

#include <map>
#include <memory>
#include <utility>

namespace shadowlab {

// Draws a shadow map as a grey image: raw depth for an ortho light, linearised between near
// and far for a perspective one; a reversed-depth map is flipped back first, so it looks the same. Usable from any context that shares the map's texture, so
// the depth-map widget samples the renderer's map directly.
class DepthViewPass {
public:
    explicit DepthViewPass(GlFunctions* gl);

    // `visible` is the part of the map shown, in map coordinates ([0, 1]^2 is the whole map,
    // y up); it is stretched over the whole target.
    void render(GLuint depthTexture, const LightFrame& light, const RenderTarget& target,
                const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0));

    // Draws moment `settings.moments.view` of a moments map as grey, decoded by the moment
    // technique `settings.filter.mode` (exponential warps undone to depth).
    void renderMoments(GLuint momentsTexture, const Settings& settings, const RenderTarget& target,
                       const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0));

private:
    struct MomentsProgram {
        MomentsProgram(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint moments, channel, exponentPositive, exponentNegative, uvOffset, uvScale;
    };
    void draw(GLuint texture);

    struct Program {
        Program(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint depth, nearPlane, farPlane, uvOffset, uvScale;
    };

    GlFunctions* m_gl;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlSampler m_sampler;
    // Variants by (perspective, reversed depth), compiled when first shown.
    std::map<std::pair<bool, bool>, std::unique_ptr<Program>> m_programs;
    std::map<QString, std::unique_ptr<MomentsProgram>> m_momentsPrograms;   // by technique variant
};

} // namespace shadowlab
