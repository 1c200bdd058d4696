#include "GlDebug.h"

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

} // namespace shadowlab
