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
    if (isSoftwareRenderer(rendererString))
        mallopt(M_TRIM_THRESHOLD, 256 << 20);
#else
    Q_UNUSED(rendererString);
#endif
}

} // namespace shadowlab
