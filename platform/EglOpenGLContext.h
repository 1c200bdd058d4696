#pragma once

#include <qpa/qplatformopenglcontext.h>

#include <QtCore/QSize>
#include <QtGui/QSurfaceFormat>
#include <QtGui/qopengl.h>

#include <EGL/egl.h>

#include <unordered_map>

namespace shadowlab {

class HeadlessWindow;

// An OpenGL context from EGL, current with no surface. Unless compatibility is asked for
// it is a core profile of at least 3.3, as with OSMesa.
//
// With no surface there is no default framebuffer, so each window the context is made
// current on gets a framebuffer object of the window's size in this context (FBOs are not
// shared): it is bound by makeCurrent(), reported by defaultFramebufferObject() (where Qt,
// QRhi and QOpenGLWidget draw "to the window"), and read back into the window's presented
// image on swapBuffers().
class EglOpenGLContext : public QPlatformOpenGLContext
{
public:
    EglOpenGLContext(QOpenGLContext *context, EGLDisplay display);
    ~EglOpenGLContext() override;

    QSurfaceFormat format() const override;
    bool makeCurrent(QPlatformSurface *surface) override;
    void doneCurrent() override;
    void swapBuffers(QPlatformSurface *surface) override;
    GLuint defaultFramebufferObject(QPlatformSurface *surface) const override;
    QFunctionPointer getProcAddress(const char *procName) override;
    bool isValid() const override;
    bool isSharing() const override;

private:
    struct WindowTarget
    {
        GLuint framebuffer = 0;
        GLuint colour = 0;
        GLuint depthStencil = 0;
        QSize size;
    };
    struct Functions;

    void readBackFormat();
    bool prepareWindowTarget(HeadlessWindow *window);
    void deleteTarget(const WindowTarget &target);
    bool isWindowFramebuffer(GLuint framebuffer) const;

    EGLDisplay m_display;
    EGLContext m_context = EGL_NO_CONTEXT;
    QSurfaceFormat m_format;
    bool m_sharing = false;
    const Functions *m_gl = nullptr;
    std::unordered_map<WId, WindowTarget> m_targets; // keyed by window id: ids are never reused
};

} // namespace shadowlab
