#include "Application.h"

#include "HeadlessPlatform.h"

#include <QCoreApplication>
#include <QSurfaceFormat>

namespace shadowlab {

void configureApplication()
{
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
}

} // namespace shadowlab
