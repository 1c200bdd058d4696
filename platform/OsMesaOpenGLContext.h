#pragma once

#include <qpa/qplatformopenglcontext.h>

#include <QtGui/QSurfaceFormat>

struct osmesa_context;

namespace shadowlab {

// An OpenGL context from OSMesa (llvmpipe). Unless compatibility is asked for
// explicitly it is a core profile of at least 3.3, because the renderer uses
// QOpenGLFunctions_3_3_Core. format() reports what Mesa actually created.
//
// OSMesa draws FBO 0 into a client buffer, which the surface provides: a window's
// render buffer (presented on swapBuffers) or an offscreen surface's scratch buffer.
class OsMesaOpenGLContext : public QPlatformOpenGLContext
{
public:
    explicit OsMesaOpenGLContext(QOpenGLContext *context);
    ~OsMesaOpenGLContext() override;

    QSurfaceFormat format() const override;
    bool makeCurrent(QPlatformSurface *surface) override;
    void doneCurrent() override;
    void swapBuffers(QPlatformSurface *surface) override;
    QFunctionPointer getProcAddress(const char *procName) override;
    bool isValid() const override;
    bool isSharing() const override;

    // OSMesa keeps writing into the buffer its current context is bound to (on every
    // flush, and when the context is released or destroyed). Surfaces call this
    // before freeing or replacing a buffer so no context is left bound to it.
    static void releaseIfDrawingTo(const void *buffer);

private:
    bool isCurrentOn(const void *buffer) const;
    void readBackFormat();

    osmesa_context *m_context = nullptr;
    QSurfaceFormat m_format;
    bool m_sharing = false;
};

} // namespace shadowlab
