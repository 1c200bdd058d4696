#include "EglDisplay.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

#include <EGL/eglext.h>

#include <array>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

namespace shadowlab {

namespace {

bool hasExtension(EGLDisplay display, const char *name)
{
    const char *extensions = eglQueryString(display, EGL_EXTENSIONS);
    return extensions && QByteArray(extensions).split(' ').contains(QByteArray(name));
}

// Creating (and dropping) a 3.3 core context is the only sure test: some displays
// initialise and then offer ES only, or no configless or surfaceless contexts.
QString coreContextProblem(EGLDisplay display)
{
    if (!hasExtension(display, "EGL_KHR_surfaceless_context"))
        return QStringLiteral("no EGL_KHR_surfaceless_context");
    if (!hasExtension(display, "EGL_KHR_no_config_context") && !hasExtension(display, "EGL_MESA_configless_context"))
        return QStringLiteral("no EGL_KHR_no_config_context");
    if (!eglBindAPI(EGL_OPENGL_API))
        return QStringLiteral("no desktop OpenGL");
    const std::array<EGLint, 7> attributes = {
        EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE,
    };
    const EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes.data());
    if (context == EGL_NO_CONTEXT)
        return QStringLiteral("no OpenGL 3.3 core context (EGL error 0x%1)").arg(eglGetError(), 0, 16);
    eglDestroyContext(display, context);
    return QString();
}

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer looks for leaks at exit, after eglTerminate has unloaded Mesa's driver; the
// driver's allocations, reachable only from its own globals, would then read as leaks of
// whoever made the context. In sanitizer builds the loaded drivers stay mapped until exit.
void keepDriversLoaded()
{
    dl_iterate_phdr(
            [](dl_phdr_info *info, size_t, void *) {
                const QByteArray name(info->dlpi_name);
                if (name.endsWith("_dri.so") || name.contains("libgallium"))
                    dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
                return 0;
            },
            nullptr);
}
#endif

} // namespace

std::unique_ptr<EglDisplay> EglDisplay::open(QString *whyNot)
{
    QStringList problems;
    const char *clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const QList<QByteArray> client = clientExtensions ? QByteArray(clientExtensions).split(' ') : QList<QByteArray>();
    const auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));

    auto tryDisplay = [&](EGLDisplay display, const QString &platform) -> std::unique_ptr<EglDisplay> {
        EGLint major = 0;
        EGLint minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
            problems << QStringLiteral("%1: cannot initialise").arg(platform);
            return nullptr;
        }
        const QString problem = coreContextProblem(display);
        if (problem.isEmpty()) {
#if defined(__SANITIZE_ADDRESS__)
            keepDriversLoaded();
#endif
            return std::unique_ptr<EglDisplay>(new EglDisplay(display, platform));
        }
        problems << QStringLiteral("%1: %2").arg(platform, problem);
        eglTerminate(display);
        return nullptr;
    };

    // SHADOWLAB_EGL_PLATFORM=surfaceless|device tries only that one (to test the device path
    // on a machine that also has surfaceless Mesa).
    const QString only = qEnvironmentVariable("SHADOWLAB_EGL_PLATFORM").toLower();
    const bool trySurfaceless = only.isEmpty() || only == u"surfaceless";
    const bool tryDevice = only.isEmpty() || only == u"device";
    if (!trySurfaceless && !tryDevice) {
        problems << QStringLiteral("SHADOWLAB_EGL_PLATFORM='%1' is neither surfaceless nor device").arg(only);
    } else if (!getPlatformDisplay) {
        problems << QStringLiteral("no eglGetPlatformDisplayEXT");
    } else {
        if (trySurfaceless && !client.contains("EGL_MESA_platform_surfaceless")) {
            problems << QStringLiteral("no EGL_MESA_platform_surfaceless");
        } else if (trySurfaceless) {
            if (auto display = tryDisplay(getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                                          QStringLiteral("surfaceless")))
                return display;
        }
        const auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        if (tryDevice && (!client.contains("EGL_EXT_platform_device") || !queryDevices)) {
            problems << QStringLiteral("no EGL_EXT_platform_device");
        } else if (tryDevice) {
            std::array<EGLDeviceEXT, 16> devices{};
            EGLint count = 0;
            if (queryDevices(EGLint(devices.size()), devices.data(), &count)) {
                for (EGLint i = 0; i < count; ++i) {
                    if (auto display = tryDisplay(getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                                                  QStringLiteral("device")))
                        return display;
                }
            }
            if (count == 0)
                problems << QStringLiteral("no EGL device");
        }
    }
    if (whyNot)
        *whyNot = problems.join(QStringLiteral("; "));
    return nullptr;
}

EglDisplay::~EglDisplay()
{
    eglTerminate(m_display);
}

} // namespace shadowlab
