#include "EglOpenGLContext.h"

#include "HeadlessWindow.h"

#include <QtCore/QRegularExpression>
#include <QtGui/QImage>
#include <QtGui/QOpenGLContext>

#include <EGL/eglext.h>

#include <array>

namespace shadowlab {

// GL entry points this class calls itself, resolved once through EGL.
struct EglOpenGLContext::Functions
{
    template <typename F>
    static F resolve(const char *name)
    {
        return reinterpret_cast<F>(eglGetProcAddress(name));
    }

    const GLubyte *(*getString)(GLenum) = resolve<const GLubyte *(*)(GLenum)>("glGetString");
    void (*getIntegerv)(GLenum, GLint *) = resolve<void (*)(GLenum, GLint *)>("glGetIntegerv");
    GLenum (*getError)() = resolve<GLenum (*)()>("glGetError");
    void (*genFramebuffers)(GLsizei, GLuint *) = resolve<void (*)(GLsizei, GLuint *)>("glGenFramebuffers");
    void (*deleteFramebuffers)(GLsizei, const GLuint *) = resolve<void (*)(GLsizei, const GLuint *)>("glDeleteFramebuffers");
    void (*bindFramebuffer)(GLenum, GLuint) = resolve<void (*)(GLenum, GLuint)>("glBindFramebuffer");
    void (*genRenderbuffers)(GLsizei, GLuint *) = resolve<void (*)(GLsizei, GLuint *)>("glGenRenderbuffers");
    void (*deleteRenderbuffers)(GLsizei, const GLuint *) = resolve<void (*)(GLsizei, const GLuint *)>("glDeleteRenderbuffers");
    void (*bindRenderbuffer)(GLenum, GLuint) = resolve<void (*)(GLenum, GLuint)>("glBindRenderbuffer");
    void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei) =
            resolve<void (*)(GLenum, GLenum, GLsizei, GLsizei)>("glRenderbufferStorage");
    void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint) =
            resolve<void (*)(GLenum, GLenum, GLenum, GLuint)>("glFramebufferRenderbuffer");
    GLenum (*checkFramebufferStatus)(GLenum) = resolve<GLenum (*)(GLenum)>("glCheckFramebufferStatus");
    void (*readPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *) =
            resolve<void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *)>("glReadPixels");
    void (*pixelStorei)(GLenum, GLint) = resolve<void (*)(GLenum, GLint)>("glPixelStorei");

    static const Functions &get()
    {
        static const Functions functions;
        return functions;
    }
};

namespace {

// The binding of the calling thread, so a temporary makeCurrent can be undone.
struct Binding
{
    EGLDisplay display = eglGetCurrentDisplay();
    EGLContext context = eglGetCurrentContext();
    EGLSurface draw = eglGetCurrentSurface(EGL_DRAW);
    EGLSurface read = eglGetCurrentSurface(EGL_READ);

    // `ours` is released when nothing was current before.
    void restore(EGLDisplay ours) const
    {
        if (context != EGL_NO_CONTEXT)
            eglMakeCurrent(display, draw, read, context);
        else
            eglMakeCurrent(ours, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
};

} // namespace

EglOpenGLContext::EglOpenGLContext(QOpenGLContext *context, EGLDisplay display)
    : m_display(display)
    , m_gl(&Functions::get())
{
    const QSurfaceFormat requested = context->format();
    const bool compatibility = requested.profile() == QSurfaceFormat::CompatibilityProfile;
    // A default QSurfaceFormat asks for 2.0, but the renderer needs QOpenGLFunctions_3_3_Core.
    const bool raise = !compatibility && requested.version() < qMakePair(3, 3);
    const int major = raise ? 3 : requested.majorVersion();
    const int minor = raise ? 3 : requested.minorVersion();
    const std::array<EGLint, 7> attributes = {
        EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor,
        EGL_CONTEXT_OPENGL_PROFILE_MASK,
        compatibility ? EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT : EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_NONE,
    };

    const auto *share = static_cast<const EglOpenGLContext *>(context->shareHandle());
    const EGLContext shareContext = share ? share->m_context : EGL_NO_CONTEXT;
    eglBindAPI(EGL_OPENGL_API);
    m_context = eglCreateContext(m_display, EGL_NO_CONFIG_KHR, shareContext, attributes.data());
    if (m_context == EGL_NO_CONTEXT) {
        qWarning("EGL: could not create an OpenGL %d.%d %s context (error 0x%x)", major, minor,
                 compatibility ? "compatibility" : "core", eglGetError());
        return;
    }
    m_sharing = shareContext != EGL_NO_CONTEXT;
    m_format = requested;
    readBackFormat();
}

EglOpenGLContext::~EglOpenGLContext()
{
    if (m_context == EGL_NO_CONTEXT)
        return;
    // Renderbuffers belong to the share group and would outlive this context; free them here.
    if (!m_targets.empty()) {
        const Binding previous;
        if (eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context)) {
            for (const auto &[id, target] : m_targets)
                deleteTarget(target);
        }
        if (previous.context != m_context)
            previous.restore(m_display);
    }
    if (eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
}

QSurfaceFormat EglOpenGLContext::format() const
{
    return m_format;
}

bool EglOpenGLContext::makeCurrent(QPlatformSurface *surface)
{
    if (m_context == EGL_NO_CONTEXT)
        return false;
    eglBindAPI(EGL_OPENGL_API);
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
        return false;

    // Windows that are gone no longer need their framebuffers.
    for (auto it = m_targets.begin(); it != m_targets.end();) {
        if (HeadlessWindow::isAlive(it->first)) {
            ++it;
        } else {
            deleteTarget(it->second);
            it = m_targets.erase(it);
        }
    }

    // Like a window system's makeCurrent, this leaves a framebuffer the caller bound alone;
    // only "the default framebuffer" (0, or another window's) is switched to this surface's.
    GLint bound = 0;
    m_gl->getIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    const bool boundIsDefault = bound == 0 || isWindowFramebuffer(GLuint(bound));
    if (surface->surface()->surfaceClass() == QSurface::Window) {
        if (!prepareWindowTarget(static_cast<HeadlessWindow *>(surface)))
            return false;
        if (boundIsDefault)
            m_gl->bindFramebuffer(GL_FRAMEBUFFER, m_targets[static_cast<HeadlessWindow *>(surface)->winId()].framebuffer);
    } else if (bound != 0 && boundIsDefault) {
        m_gl->bindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    return true;
}

void EglOpenGLContext::doneCurrent()
{
    if (eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

void EglOpenGLContext::swapBuffers(QPlatformSurface *surface)
{
    if (surface->surface()->surfaceClass() != QSurface::Window)
        return;
    auto *window = static_cast<HeadlessWindow *>(surface);
    const auto found = m_targets.find(window->winId());
    if (eglGetCurrentContext() != m_context || found == m_targets.end()) {
        qWarning("EGL: swapBuffers() needs the context to be current on the window");
        return;
    }
    const WindowTarget &target = found->second;
    GLint previousRead = 0;
    GLint previousAlignment = 4;
    m_gl->getIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    m_gl->getIntegerv(GL_PACK_ALIGNMENT, &previousAlignment);
    m_gl->bindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer);
    m_gl->pixelStorei(GL_PACK_ALIGNMENT, 4);
    QImage frame(target.size, window->window()->format().hasAlpha() ? QImage::Format_RGBA8888_Premultiplied
                                                                     : QImage::Format_RGBX8888);
    m_gl->readPixels(0, 0, target.size.width(), target.size.height(), GL_RGBA, GL_UNSIGNED_BYTE, frame.bits());
    m_gl->pixelStorei(GL_PACK_ALIGNMENT, previousAlignment);
    m_gl->bindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previousRead));
    // GL's rows run bottom-up, QImage's top-down.
    window->presentFrame(frame.mirrored(false, true));
}

GLuint EglOpenGLContext::defaultFramebufferObject(QPlatformSurface *surface) const
{
    if (!surface || surface->surface()->surfaceClass() != QSurface::Window)
        return 0;
    const auto found = m_targets.find(static_cast<HeadlessWindow *>(surface)->winId());
    return found == m_targets.end() ? 0 : found->second.framebuffer;
}

QFunctionPointer EglOpenGLContext::getProcAddress(const char *procName)
{
    return eglGetProcAddress(procName);
}

bool EglOpenGLContext::isValid() const
{
    return m_context != EGL_NO_CONTEXT;
}

bool EglOpenGLContext::isSharing() const
{
    return m_sharing;
}

bool EglOpenGLContext::prepareWindowTarget(HeadlessWindow *window)
{
    const QSize size = window->geometry().size().expandedTo(QSize(1, 1));
    WindowTarget &target = m_targets[window->winId()];
    if (target.framebuffer && target.size == size)
        return true;
    if (!target.framebuffer) {
        m_gl->genFramebuffers(1, &target.framebuffer);
        m_gl->genRenderbuffers(1, &target.colour);
        m_gl->genRenderbuffers(1, &target.depthStencil);
    }
    target.size = size;
    GLint previousRenderbuffer = 0;
    GLint previousFramebuffer = 0;
    m_gl->getIntegerv(GL_RENDERBUFFER_BINDING, &previousRenderbuffer);
    m_gl->getIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    m_gl->bindRenderbuffer(GL_RENDERBUFFER, target.colour);
    m_gl->renderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
    m_gl->bindRenderbuffer(GL_RENDERBUFFER, target.depthStencil);
    m_gl->renderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.width(), size.height());
    m_gl->bindRenderbuffer(GL_RENDERBUFFER, GLuint(previousRenderbuffer));
    m_gl->bindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    m_gl->framebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, target.colour);
    m_gl->framebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, target.depthStencil);
    const GLenum status = m_gl->checkFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    m_gl->bindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previousFramebuffer));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        qWarning("EGL: the %dx%d framebuffer of a window is incomplete (0x%x)", size.width(), size.height(), status);
        return false;
    }
    return true;
}

void EglOpenGLContext::deleteTarget(const WindowTarget &target)
{
    m_gl->deleteFramebuffers(1, &target.framebuffer);
    const std::array<GLuint, 2> renderbuffers = { target.colour, target.depthStencil };
    m_gl->deleteRenderbuffers(GLsizei(renderbuffers.size()), renderbuffers.data());
}

bool EglOpenGLContext::isWindowFramebuffer(GLuint framebuffer) const
{
    for (const auto &[id, target] : m_targets) {
        if (target.framebuffer == framebuffer)
            return true;
    }
    return false;
}

void EglOpenGLContext::readBackFormat()
{
    // Version and profile can only be asked of a current context, and creating a context
    // must not disturb whatever the caller has current.
    const Binding previous;
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context)) {
        previous.restore(m_display);
        return;
    }

    const QString version = QString::fromLatin1(reinterpret_cast<const char *>(m_gl->getString(GL_VERSION)));
    const QRegularExpressionMatch match = QRegularExpression(QStringLiteral("^(\\d+)\\.(\\d+)")).match(version);
    const int major = match.captured(1).toInt();
    const int minor = match.captured(2).toInt();
    m_format.setRenderableType(QSurfaceFormat::OpenGL);
    m_format.setVersion(major, minor);
    m_format.setProfile(QSurfaceFormat::NoProfile);
    if (qMakePair(major, minor) >= qMakePair(3, 2)) {
        GLint profileMask = 0;
        m_gl->getIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
        if (profileMask & GL_CONTEXT_CORE_PROFILE_BIT)
            m_format.setProfile(QSurfaceFormat::CoreProfile);
        else if (profileMask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT)
            m_format.setProfile(QSurfaceFormat::CompatibilityProfile);
    }
    if (major >= 3) {
        GLint flags = 0;
        m_gl->getIntegerv(GL_CONTEXT_FLAGS, &flags);
        m_format.setOption(QSurfaceFormat::DebugContext, flags & GL_CONTEXT_FLAG_DEBUG_BIT);
        m_format.setOption(QSurfaceFormat::DeprecatedFunctions, !(flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT));
    }
    // What a window's framebuffer holds (prepareWindowTarget).
    m_format.setRedBufferSize(8);
    m_format.setGreenBufferSize(8);
    m_format.setBlueBufferSize(8);
    m_format.setAlphaBufferSize(8);
    m_format.setDepthBufferSize(24);
    m_format.setStencilBufferSize(8);
    m_format.setSamples(0);
    m_format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    m_gl->getError(); // a query the context lacks must not leave an error for the caller

    previous.restore(m_display);
}

} // namespace shadowlab
