#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace shadowlab {

// Makes the app, CLI and tests runnable with no display server. Call it first thing
// in main(), before the Q(Gui)Application exists: it pulls in the static "headless"
// platform plugin and, when nothing says otherwise (QT_QPA_PLATFORM unset and no
// DISPLAY or WAYLAND_DISPLAY), selects it. An explicit QT_QPA_PLATFORM or
// "-platform <name>" argument always wins.
void selectPlatformForHeadlessUse();

// The names the headless plugin answers to: headless, egl, osmesa.
QStringList headlessPlatformNames();

// While the headless platform is in use: "egl-surfaceless", "egl-device" or "osmesa";
// empty otherwise.
QString activeHeadlessBackend();
void setActiveHeadlessBackend(const QString &backend);

} // namespace shadowlab

namespace shadowlab {

// Every platform name Qt could load here (its plugins and the headless ones).
QStringList availablePlatformNames();

} // namespace shadowlab
