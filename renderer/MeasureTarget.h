#pragma once

#include "GlObject.h"
#include "RenderTarget.h"
#include "VisibilityBuffer.h"

#include <glm/vec3.hpp>

namespace shadowlab {

// A framebuffer with an RGBA8 colour, four RGBA32F measurement attachments (position and
// visibility, normal and mask, ambient and direct light) and depth, for the lit pass's MEASURE
// variant. The attachments of the size before are kept too: a flicker walk that alternates a
// full-size frame with a small one reallocates nothing (16 MB a switch at 640x360).
class MeasureTarget {
public:
    explicit MeasureTarget(GlFunctions* gl);

    // Makes `size`'s attachments current, allocating them unless this or the size before had
    // them; throws RenderError when the framebuffer is incomplete.
    RenderTarget ensure(QSize size);
    // The current attachments' pixels.
    VisibilityBuffer read(const glm::dvec3& cameraPosition) const;

private:
    struct Attachments {
        QSize size;
        GlFramebuffer framebuffer;
        GlTexture color, position, normal, ambient, direct, depth;
    };
    Attachments allocate(QSize size) const;

    GlFunctions* m_gl;
    Attachments m_current;
    Attachments m_before;
};

} // namespace shadowlab
