#pragma once

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>

namespace shadowlab {

// Where a pass draws: a framebuffer of the current context (a widget's
// defaultFramebufferObject(), never a hard-coded 0) and its size in pixels.
struct RenderTarget {
    GLuint framebuffer = 0;
    QSize size;
};

} // namespace shadowlab
