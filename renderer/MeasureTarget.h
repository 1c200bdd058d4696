#pragma once

#include "GlObject.h"
#include "RenderTarget.h"
#include "VisibilityBuffer.h"

#include <glm/vec3.hpp>

namespace shadowlab {

// A framebuffer with an RGBA8 colour, four RGBA32F measurement attachments (position and
// visibility, normal and mask, ambient and direct light) and depth, for the lit pass's MEASURE
// variant.
class MeasureTarget {
public:
    explicit MeasureTarget(GlFunctions* gl);

    // (Re)allocates for `size`; throws RenderError when the framebuffer is incomplete.
    RenderTarget ensure(QSize size);
    VisibilityBuffer read(const glm::dvec3& cameraPosition) const;

private:
    GlFunctions* m_gl;
    GlFramebuffer m_framebuffer;
    GlTexture m_color;
    GlTexture m_position;
    GlTexture m_normal;
    GlTexture m_ambient;
    GlTexture m_direct;
    GlTexture m_depth;
    QSize m_size;
};

} // namespace shadowlab
