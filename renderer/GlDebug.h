#pragma once

namespace shadowlab {

// With SHADOWLAB_GL_DEBUG (on in the debug and sanitize presets): attaches a
// QOpenGLDebugLogger to the current context, once, that makes every GL error fatal where it
// happens, so a test that provokes one fails there, and passes other driver messages to
// qDebug. Without it, or where the context lacks KHR_debug, does nothing.
void installGlDebugLogger();

} // namespace shadowlab
