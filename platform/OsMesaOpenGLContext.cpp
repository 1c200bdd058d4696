#include "OsMesaOpenGLContext.h"

#include "HeadlessOffscreenSurface.h"
#include "HeadlessWindow.h"

#include <QtCore/QRegularExpression>
#include <QtGui/QOpenGLContext>

#include <GL/osmesa.h>

#include <array>
#include <cstdint>

namespace shadowlab {

namespace {

// GL entry points are always looked up through OSMesa: libOpenGL (GLVND, pulled in by
// QtGui) exports the same names and would dispatch to a context that doesn't exist.
template <typename Function>
Function glFunction(const char *name)
{
    return reinterpret_cast<Function>(OSMesaGetProcAddress(name));
}

using GetStringFn = const GLubyte *(*)(GLenum);
using GetIntegervFn = void (*)(GLenum, GLint *);
using GetFramebufferAttachmentParameterivFn = void (*)(GLenum, GLenum, GLenum, GLint *);
using GetErrorFn = GLenum (*)();
using FinishFn = void (*)();

struct ProfileRequest
{
    int profile;
    int major;
    int minor;
};

ProfileRequest profileFor(const QSurfaceFormat &requested)
{
    if (requested.profile() == QSurfaceFormat::CompatibilityProfile)
        return { OSMESA_COMPAT_PROFILE, requested.majorVersion(), requested.minorVersion() };
    // Everything else gets core, and never less than 3.3: a default QSurfaceFormat
    // asks for 2.0, but the renderer needs QOpenGLFunctions_3_3_Core.
    if (requested.version() < qMakePair(3, 3))
        return { OSMESA_CORE_PROFILE, 3, 3 };
    return { OSMESA_CORE_PROFILE, requested.majorVersion(), requested.minorVersion() };
}

// The binding of the calling thread, so a temporary makeCurrent can be undone.
struct Binding
{
    OSMesaContext context = nullptr;
    void *buffer = nullptr;
    GLint width = 0;
    GLint height = 0;

    static Binding current()
    {
        Binding binding;
        binding.context = OSMesaGetCurrentContext();
        GLint format = 0;
        if (binding.context)
            OSMesaGetColorBuffer(binding.context, &binding.width, &binding.height, &format, &binding.buffer);
        return binding;
    }

    void restore() const
    {
        if (context)
            OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, width, height);
        else
            OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    }
};

} // namespace

OsMesaOpenGLContext::OsMesaOpenGLContext(QOpenGLContext *context)
{
    const QSurfaceFormat requested = context->format();
    const ProfileRequest profile = profileFor(requested);
    const int depthBits = requested.depthBufferSize() < 0 ? 24 : requested.depthBufferSize();
    const int stencilBits = requested.stencilBufferSize() < 0 ? 8 : requested.stencilBufferSize();
    const std::array<int, 15> attributes = {
        OSMESA_FORMAT, OSMESA_RGBA,
        OSMESA_DEPTH_BITS, depthBits,
        OSMESA_STENCIL_BITS, stencilBits,
        OSMESA_ACCUM_BITS, 0,
        OSMESA_PROFILE, profile.profile,
        OSMESA_CONTEXT_MAJOR_VERSION, profile.major,
        OSMESA_CONTEXT_MINOR_VERSION, profile.minor,
        0,
    };

    const auto *share = static_cast<const OsMesaOpenGLContext *>(context->shareHandle());
    OSMesaContext shareContext = share ? share->m_context : nullptr;
    m_context = OSMesaCreateContextAttribs(attributes.data(), shareContext);
    if (!m_context) {
        qWarning("OSMesa: could not create an OpenGL %d.%d %s context", profile.major, profile.minor,
                 profile.profile == OSMESA_CORE_PROFILE ? "core" : "compatibility");
        return;
    }
    m_sharing = shareContext != nullptr;
    m_format = requested;
    readBackFormat();
}

OsMesaOpenGLContext::~OsMesaOpenGLContext()
{
    if (!m_context)
        return;
    if (OSMesaGetCurrentContext() == m_context)
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(m_context);
}

QSurfaceFormat OsMesaOpenGLContext::format() const
{
    return m_format;
}

bool OsMesaOpenGLContext::makeCurrent(QPlatformSurface *surface)
{
    if (!m_context)
        return false;

    void *pixels = nullptr;
    QSize size;
    if (surface->surface()->surfaceClass() == QSurface::Window) {
        const HeadlessWindow::RenderBuffer buffer = static_cast<HeadlessWindow *>(surface)->renderBuffer();
        pixels = buffer.pixels;
        size = buffer.size;
    } else {
        auto *offscreen = static_cast<HeadlessOffscreenSurface *>(surface);
        pixels = offscreen->pixels();
        size = offscreen->size();
    }
    return OSMesaMakeCurrent(m_context, pixels, GL_UNSIGNED_BYTE, size.width(), size.height()) == GL_TRUE;
}

void OsMesaOpenGLContext::doneCurrent()
{
    if (m_context && OSMesaGetCurrentContext() == m_context)
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
}

void OsMesaOpenGLContext::swapBuffers(QPlatformSurface *surface)
{
    if (surface->surface()->surfaceClass() != QSurface::Window)
        return;
    auto *window = static_cast<HeadlessWindow *>(surface);
    if (!isCurrentOn(window->renderPixels())) {
        qWarning("OSMesa: swapBuffers() needs the context to be current on the window");
        return;
    }
    // OSMesa copies FBO 0 into the client buffer when the frame is flushed.
    glFunction<FinishFn>("glFinish")();
    window->presentRenderBuffer();
}

QFunctionPointer OsMesaOpenGLContext::getProcAddress(const char *procName)
{
    return OSMesaGetProcAddress(procName);
}

bool OsMesaOpenGLContext::isValid() const
{
    return m_context != nullptr;
}

bool OsMesaOpenGLContext::isSharing() const
{
    return m_sharing;
}

void OsMesaOpenGLContext::releaseIfDrawingTo(const void *buffer)
{
    if (!buffer || !OSMesaGetCurrentContext())
        return;
    if (Binding::current().buffer == buffer)
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
}

bool OsMesaOpenGLContext::isCurrentOn(const void *buffer) const
{
    const Binding binding = Binding::current();
    return binding.context == m_context && binding.buffer == buffer;
}

void OsMesaOpenGLContext::readBackFormat()
{
    // Version, profile and buffer sizes can only be asked of a current context, and
    // creating a context must not disturb whatever the caller has current.
    const Binding previous = Binding::current();
    std::array<std::uint32_t, 1> scratch{};
    if (!OSMesaMakeCurrent(m_context, scratch.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        previous.restore();
        return;
    }

    const auto getString = glFunction<GetStringFn>("glGetString");
    const auto getIntegerv = glFunction<GetIntegervFn>("glGetIntegerv");
    const auto getAttachmentParameter =
            glFunction<GetFramebufferAttachmentParameterivFn>("glGetFramebufferAttachmentParameteriv");

    // GL_VERSION reads "<major>.<minor>[.<release>] <vendor info>" in every profile.
    const QString version = QString::fromLatin1(reinterpret_cast<const char *>(getString(GL_VERSION)));
    const QRegularExpressionMatch match = QRegularExpression(QStringLiteral("^(\\d+)\\.(\\d+)")).match(version);
    const int major = match.captured(1).toInt();
    const int minor = match.captured(2).toInt();
    m_format.setRenderableType(QSurfaceFormat::OpenGL);
    m_format.setVersion(major, minor);

    m_format.setProfile(QSurfaceFormat::NoProfile);
    if (qMakePair(major, minor) >= qMakePair(3, 2)) {
        GLint profileMask = 0;
        getIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
        if (profileMask & GL_CONTEXT_CORE_PROFILE_BIT)
            m_format.setProfile(QSurfaceFormat::CoreProfile);
        else if (profileMask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT)
            m_format.setProfile(QSurfaceFormat::CompatibilityProfile);
    }
    if (major >= 3) {
        GLint flags = 0;
        getIntegerv(GL_CONTEXT_FLAGS, &flags);
        m_format.setOption(QSurfaceFormat::DebugContext, flags & GL_CONTEXT_FLAG_DEBUG_BIT);
        m_format.setOption(QSurfaceFormat::DeprecatedFunctions, !(flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT));
    }

    // Mesa rounds depth/stencil requests to the formats it has; ask the default
    // framebuffer what it got. Querying a missing attachment's size is an error, so
    // look at its type first.
    const auto attachmentSize = [&](GLenum attachment, GLenum parameter) {
        GLint type = GL_NONE;
        getAttachmentParameter(GL_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        GLint size = 0;
        if (type != GL_NONE)
            getAttachmentParameter(GL_FRAMEBUFFER, attachment, parameter, &size);
        return size;
    };
    m_format.setRedBufferSize(attachmentSize(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE));
    m_format.setGreenBufferSize(attachmentSize(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE));
    m_format.setBlueBufferSize(attachmentSize(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE));
    m_format.setAlphaBufferSize(attachmentSize(GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE));
    m_format.setDepthBufferSize(attachmentSize(GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE));
    m_format.setStencilBufferSize(attachmentSize(GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE));
    m_format.setSamples(0);
    // The frame becomes visible only on swapBuffers(), which is what double
    // buffering means to callers, even though OSMesa itself has a single buffer.
    m_format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);

    // A query the context doesn't support must not leave an error for the caller's
    // first glGetError() to find. Mesa keeps a single error flag; one read clears it.
    glFunction<GetErrorFn>("glGetError")();

    previous.restore();
}

} // namespace shadowlab
