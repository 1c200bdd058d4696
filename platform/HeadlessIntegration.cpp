#include "HeadlessIntegration.h"

#include "EglDisplay.h"
#include "EglOpenGLContext.h"
#include "HeadlessBackingStore.h"
#include "HeadlessPlatform.h"
#include "HeadlessOffscreenSurface.h"
#include "HeadlessScreen.h"
#include "HeadlessTheme.h"
#include "HeadlessWindow.h"
#ifdef SHADOWLAB_HAVE_OSMESA
#include "OsMesaOpenGLContext.h"
#endif

#include <QtGui/private/qgenericunixeventdispatcher_p.h>
#include <QtGui/private/qgenericunixfontdatabase_p.h>
#include <qpa/qplatformservices.h>
#include <qpa/qwindowsysteminterface.h>

namespace shadowlab {

namespace {
const QString themeName = QStringLiteral("headless");
}

HeadlessIntegration::HeadlessIntegration(std::unique_ptr<EglDisplay> egl)
    : m_egl(std::move(egl))
    , m_fontDatabase(std::make_unique<QGenericUnixFontDatabase>())
    , m_services(std::make_unique<QPlatformServices>())
    , m_screen(new HeadlessScreen)
{
    QWindowSystemInterface::handleScreenAdded(m_screen, true);
    setActiveHeadlessBackend(m_egl ? QStringLiteral("egl-") + m_egl->platform() : QStringLiteral("osmesa"));
}

HeadlessIntegration::~HeadlessIntegration()
{
    // Hands the screen back to QtGui, which moves remaining windows off it and deletes it.
    QWindowSystemInterface::handleScreenRemoved(m_screen);
    setActiveHeadlessBackend(QString());
}

bool HeadlessIntegration::hasCapability(Capability cap) const
{
    switch (cap) {
    case OpenGL:
    case AllGLFunctionsQueryable: // OSMesaGetProcAddress and Mesa's eglGetProcAddress resolve GL 1.0 entry points too
    case MultipleWindows:
    case NonFullScreenWindows:
    case ThreadedPixmaps:
    case ScreenWindowGrabbing:
        return true;
    // Window pixels live in client memory whatever the surface type, so a window can
    // be painted by the raster engine and by GL, and switch between the two. Needed
    // for QOpenGLWidget, whose top-level is composed through QRhi's GL backend.
    case RasterGLSurface:
    case OpenGLOnRasterSurface:
    case SwitchableWidgetComposition:
    case RhiBasedRendering:
        return true;
    // Window buffers are resized on the GUI thread with no locking, and nothing here
    // needs a render thread; saying no makes Qt pick its single-threaded GL paths.
    case ThreadedOpenGL:
        return false;
    // swapBuffers() finishes the frame synchronously; there is no queue to exploit.
    case BufferQueueingOpenGL:
        return false;
    default:
        return QPlatformIntegration::hasCapability(cap);
    }
}

QPlatformWindow *HeadlessIntegration::createPlatformWindow(QWindow *window) const
{
    return new HeadlessWindow(window);
}

QPlatformBackingStore *HeadlessIntegration::createPlatformBackingStore(QWindow *window) const
{
    return new HeadlessBackingStore(window);
}

QPlatformOpenGLContext *HeadlessIntegration::createPlatformOpenGLContext(QOpenGLContext *context) const
{
    if (m_egl)
        return new EglOpenGLContext(context, m_egl->handle());
#ifdef SHADOWLAB_HAVE_OSMESA
    return new OsMesaOpenGLContext(context);
#else
    return nullptr;
#endif
}

QPlatformOffscreenSurface *HeadlessIntegration::createPlatformOffscreenSurface(QOffscreenSurface *surface) const
{
    return new HeadlessOffscreenSurface(surface);
}

QAbstractEventDispatcher *HeadlessIntegration::createEventDispatcher() const
{
    return createUnixEventDispatcher();
}

QPlatformFontDatabase *HeadlessIntegration::fontDatabase() const
{
    return m_fontDatabase.get();
}

QPlatformServices *HeadlessIntegration::services() const
{
    return m_services.get();
}

QStringList HeadlessIntegration::themeNames() const
{
    return { themeName };
}

QPlatformTheme *HeadlessIntegration::createPlatformTheme(const QString &name) const
{
    return name == themeName ? new HeadlessTheme : nullptr;
}

} // namespace shadowlab
