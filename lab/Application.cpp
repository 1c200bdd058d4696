#include "Application.h"

#include "HeadlessPlatform.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QSurfaceFormat>

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

} // namespace

QString versionText()
{
    return QStringLiteral("shadowlab %1\n%2\nLicence: %3 (see LICENSE, or Help → About ShadowLab).\n"
                          "This is free software: you are free to change and redistribute it.\n"
                          "There is NO WARRANTY, to the extent permitted by law.\n")
        .arg(QStringLiteral(SHADOWLAB_VERSION), QLatin1String(kCopyrightLine), QLatin1String(kLicenceName));
}

void configureApplication()
{
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
