#include "OsMesaIntegration.h"

#include "OsMesaBackingStore.h"
#include "OsMesaOffscreenSurface.h"
#include "OsMesaOpenGLContext.h"
#include "OsMesaScreen.h"
#include "OsMesaTheme.h"
#include "OsMesaWindow.h"

#include <QtGui/private/qgenericunixeventdispatcher_p.h>
#include <QtGui/private/qgenericunixfontdatabase_p.h>
#include <qpa/qplatformservices.h>
#include <qpa/qwindowsysteminterface.h>

namespace shadowlab {

namespace {
const QString themeName = QStringLiteral("osmesa");
}

OsMesaIntegration::OsMesaIntegration()
    : m_fontDatabase(std::make_unique<QGenericUnixFontDatabase>())
    , m_services(std::make_unique<QPlatformServices>())
    , m_screen(new OsMesaScreen)
{
    QWindowSystemInterface::handleScreenAdded(m_screen, true);
}

OsMesaIntegration::~OsMesaIntegration()
{
    // Hands the screen back to QtGui, which moves remaining windows off it and deletes it.
    QWindowSystemInterface::handleScreenRemoved(m_screen);
}

bool OsMesaIntegration::hasCapability(Capability cap) const
{
    switch (cap) {
    case OpenGL:
    case AllGLFunctionsQueryable: // OSMesaGetProcAddress resolves GL 1.0 entry points too
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

QPlatformWindow *OsMesaIntegration::createPlatformWindow(QWindow *window) const
{
    return new OsMesaWindow(window);
}

QPlatformBackingStore *OsMesaIntegration::createPlatformBackingStore(QWindow *window) const
{
    return new OsMesaBackingStore(window);
}

QPlatformOpenGLContext *OsMesaIntegration::createPlatformOpenGLContext(QOpenGLContext *context) const
{
    return new OsMesaOpenGLContext(context);
}

QPlatformOffscreenSurface *OsMesaIntegration::createPlatformOffscreenSurface(QOffscreenSurface *surface) const
{
    return new OsMesaOffscreenSurface(surface);
}

QAbstractEventDispatcher *OsMesaIntegration::createEventDispatcher() const
{
    return createUnixEventDispatcher();
}

QPlatformFontDatabase *OsMesaIntegration::fontDatabase() const
{
    return m_fontDatabase.get();
}

QPlatformServices *OsMesaIntegration::services() const
{
    return m_services.get();
}

QStringList OsMesaIntegration::themeNames() const
{
    return { themeName };
}

QPlatformTheme *OsMesaIntegration::createPlatformTheme(const QString &name) const
{
    return name == themeName ? new OsMesaTheme : nullptr;
}

} // namespace shadowlab
