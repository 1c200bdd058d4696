#pragma once

#include <QString>

namespace shadowlab {

// Whether `rendererString` (GL_RENDERER and friends) names a software rasteriser, whose "GPU"
// times are CPU times and whose timer queries miss its deferred work.
bool isSoftwareRenderer(const QString& rendererString);

// A software rasteriser (llvmpipe) allocates its binning memory per frame, in proportion to
// the target's tiles, and frees it when the frame is done; glibc hands the freed top of its
// heaps back to the kernel, so every frame pays the page faults again (at a 2048² shadow map
// drawn every frame, a sixth of the frame). Its textures and a measurement's read-backs (16 MB
// a frame at 640x360) come and go the same way. With `rendererString` a software rasteriser's,
// blocks up to 256 MiB come from the heap, not fresh mappings, and up to 256 MiB freed stays
// with the process (half of `report`'s time went to those page faults). Process-wide; a GPU
// driver's process is left as it is.
void keepFreedMemoryForSoftwareRasteriser(const QString& rendererString);

// With SHADOWLAB_GL_DEBUG (on in the debug and sanitize presets): attaches a
// QOpenGLDebugLogger to the current context, once, that makes every GL error fatal where it
// happens, so a test that provokes one fails there, and passes other driver messages to
// qDebug. Without it, or where the context lacks KHR_debug, does nothing.
void installGlDebugLogger();

} // namespace shadowlab
