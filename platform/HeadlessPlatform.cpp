#include "HeadlessPlatform.h"

#include <QtCore/QByteArray>
#include <QtCore/QtPlugin>
#include <qpa/qplatformintegrationfactory_p.h>

// Lives in the same object file as selectPlatformForHeadlessUse() so that calling the
// function is what makes the linker keep the plugin registration.
Q_IMPORT_PLUGIN(HeadlessIntegrationPlugin)

#if defined(__SANITIZE_ADDRESS__)
// Mesa 22's OSMesa never frees its per-process state and per-size framebuffer records,
// even for a context made current, released and destroyed by the book, and its EGL driver
// keeps per-process state too; without this every GL test would fail LeakSanitizer at
// exit. Leaks of ours still show: a context we failed to destroy is owned by an
// OsMesaOpenGLContext or EglOpenGLContext allocated from Qt, not Mesa.
extern "C" const char *__lsan_default_suppressions()
{
    return "leak:libOSMesa.so\nleak:libEGL_mesa.so\nleak:libgallium\n";
}
#endif

namespace shadowlab {

void selectPlatformForHeadlessUse()
{
    // Qt treats an empty QT_QPA_PLATFORM as unset, and an empty DISPLAY is no display.
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        return;
    if (!qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        return;
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("headless"));
}

QStringList headlessPlatformNames()
{
    return { QStringLiteral("headless"), QStringLiteral("egl"), QStringLiteral("osmesa") };
}

QStringList availablePlatformNames()
{
    QStringList names = QPlatformIntegrationFactory::keys() + headlessPlatformNames();
    names.removeDuplicates();
#ifndef SHADOWLAB_HAVE_OSMESA
    names.removeAll(QStringLiteral("osmesa")); // the plugin's key, but this build has no OSMesa
#endif
    return names;
}

namespace {
QString &activeBackend()
{
    static QString name;
    return name;
}
} // namespace

QString activeHeadlessBackend()
{
    return activeBackend();
}

void setActiveHeadlessBackend(const QString &backend)
{
    activeBackend() = backend;
}

} // namespace shadowlab
