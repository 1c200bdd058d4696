#include "Application.h"

#include "HeadlessPlatform.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QSurfaceFormat>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace shadowlab {

namespace {

QtMessageHandler g_previousHandler = nullptr;

// Qt warns on every start where XDG_RUNTIME_DIR is unset (a container, a CI job, a cron job)
// and then uses its own fallback folder: nothing for a user to act on, and it would be the
// first line of every command's output. Every other message passes on.
void dropRuntimeDirNotice(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtWarningMsg && message.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    if (g_previousHandler)
        g_previousHandler(type, context, message);
}

// A measurement allocates and frees buffers of megabytes many times a second: each frame's
// read-back (16 MB at 640x360), the software renderer's textures (a 2048 moments map is
// 64 MB). glibc hands such blocks back to the kernel when freed, and the next one is faulted
// in page by page: half of `report`'s time went there. Blocks up to 256 MB stay in the heap
// and up to 256 MB of it is kept free for the next.
void keepLargeBlocksInTheHeap()
{
#ifdef __GLIBC__
    // Older glibc refuses a threshold above 32 MB; the trim threshold is set only with a
    // threshold that took, as setting it freezes the threshold glibc would otherwise raise.
    constexpr int kLargest = 256 << 20, kOlderLargest = 32 << 20;
    if (mallopt(M_MMAP_THRESHOLD, kLargest) == 1 || mallopt(M_MMAP_THRESHOLD, kOlderLargest) == 1)
        mallopt(M_TRIM_THRESHOLD, kLargest);
#endif
}

} // namespace

void configureApplication()
{
    keepLargeBlocksInTheHeap();
    if (!g_previousHandler)
        g_previousHandler = qInstallMessageHandler(dropRuntimeDirNotice);
    selectPlatformForHeadlessUse();
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QCoreApplication::setOrganizationName(QStringLiteral("ShadowLab"));
    QCoreApplication::setApplicationName(QStringLiteral("ShadowLab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SHADOWLAB_VERSION));
    // The installed desktop entry (packaging/): how a Wayland desktop finds the window's icon and name.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.shadowlab.ShadowLab"));
}

} // namespace shadowlab
