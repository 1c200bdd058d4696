#pragma once

#include "DepthRangePass.h"
#include "LightMath.h"
#include "ProgramCache.h"
#include "RenderTarget.h"
#include "Settings.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

#include <QImage>
#include <QRect>
#include <QRectF>

#include <memory>
#include <optional>
#include <utility>

namespace shadowlab {

// The depths a shadow map really holds: its nearest and farthest written texel, in conventional
// [0, 1] depth (0 at the light's near plane), whatever the map's storage.
struct DepthSpan {
    double nearest = 0.0;
    double farthest = 1.0;
};

// Draws a shadow map through a perceptual colour ramp (shaders/ramp.glsl) stretched to the
// depths its texels hold: raw depth for an ortho light, linearised between near and far for a
// perspective one; a reversed-depth map is flipped back first, so it looks the same. Empty
// texels (the far plane) are hatched grey. Usable from any context that shares the map's
// texture, so the depth-map widget samples the renderer's map directly.
class DepthViewPass {
public:
    explicit DepthViewPass(GlFunctions* gl);
    ~DepthViewPass();

    // The written range of `map` (nullopt when nothing was drawn into it). Reads back one texel
    // of a min/max reduction: call it once per shadow pass, not per frame.
    std::optional<DepthSpan> measure(const ShadowMap& map, const LightFrame& light);

    // `visible` is the part of the map shown, in map coordinates ([0, 1]^2 is the whole map,
    // y up); it is stretched over `viewport` (GL pixels, y up; empty: the whole target).
    // `span` stretches the ramp (nullopt: the whole [0, 1]).
    void render(const ShadowMap& map, const LightFrame& light, const RenderTarget& target,
                const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0), const QRect& viewport = QRect(),
                const std::optional<DepthSpan>& span = std::nullopt);
    // The ramp itself from near (left) to far (right) over `viewport`: the legend's colour bar.
    void renderLegend(const RenderTarget& target, const QRect& viewport);
    // `image` (premultiplied RGBA, the target's size, top row first) blended over the target:
    // the picture's text and outlines, painted with QPainter's raster engine.
    void renderOverlay(const RenderTarget& target, const QImage& image);

    // Draws moment `settings.moments.view` of a moments map as grey, decoded by the moment
    // technique `settings.filter.mode` (exponential warps undone to depth).
    void renderMoments(GLuint momentsTexture, const Settings& settings, const RenderTarget& target,
                       const QRectF& visible = QRectF(0.0, 0.0, 1.0, 1.0), const QRect& viewport = QRect());

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
        GLint depth, nearPlane, farPlane, uvOffset, uvScale, span, slice;
    };

    GlFunctions* m_gl;
    GlVertexArray m_emptyVertexArray;   // core profile draws need a bound VAO
    GlSampler m_sampler;
    std::unique_ptr<DepthRangePass> m_range;    // built on first measure()
    GlTexture m_overlay;                        // built on first renderOverlay()
    // Variants by their defines (perspective, reversed depth, legend), compiled when first shown.
    ProgramCache<Program> m_programs;
    ProgramCache<MomentsProgram> m_momentsPrograms;     // by technique variant
};

} // namespace shadowlab
