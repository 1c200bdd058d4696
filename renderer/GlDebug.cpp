#include "GlDebug.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#ifdef SHADOWLAB_GL_DEBUG
#include <QOpenGLContext>
#include <QOpenGLDebugLogger>
#endif

namespace shadowlab {

void installGlDebugLogger()
{
#ifdef SHADOWLAB_GL_DEBUG
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (!context || context->findChild<QOpenGLDebugLogger*>() || !context->hasExtension(QByteArrayLiteral("GL_KHR_debug")))
        return;
    auto* logger = new QOpenGLDebugLogger(context);
    if (!logger->initialize()) {
        delete logger;
        return;
    }
    QObject::connect(logger, &QOpenGLDebugLogger::messageLogged, logger, [](const QOpenGLDebugMessage& message) {
        if (message.type() == QOpenGLDebugMessage::ErrorType)
            qFatal("GL error: %s", qPrintable(message.message()));
        qDebug("GL: %s", qPrintable(message.message()));
    });
    // Synchronous: the error is reported inside the call that caused it, with its stack.
    logger->startLogging(QOpenGLDebugLogger::SynchronousLogging);
#endif
}

bool isSoftwareRenderer(const QString& rendererString)
{
    const QString r = rendererString.toLower();
    return r.contains(QLatin1String("llvmpipe")) || r.contains(QLatin1String("softpipe")) || r.contains(QLatin1String("swrast"))
        || r.contains(QLatin1String("software"));
}

void keepFreedMemoryForSoftwareRasteriser(const QString& rendererString)
{
#ifdef __GLIBC__
    if (!isSoftwareRenderer(rendererString))
        return;
    // The threshold first: setting the trim threshold alone freezes glibc's mmap threshold at
    // 128 KiB, so every larger block (a 16 MB read-back, a texture) was mapped fresh and faulted
    // in page by page. Older glibc refuses a threshold above 32 MB.
    constexpr int kLargest = 256 << 20, kOlderLargest = 32 << 20;
    if (mallopt(M_MMAP_THRESHOLD, kLargest) == 1 || mallopt(M_MMAP_THRESHOLD, kOlderLargest) == 1)
        mallopt(M_TRIM_THRESHOLD, kLargest);
#else
    Q_UNUSED(rendererString);
#endif
}

} // namespace shadowlab
