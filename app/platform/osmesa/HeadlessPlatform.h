#pragma once

namespace shadowlab {

// Makes the app, CLI and tests runnable with no display server. Call it first thing
// in main(), before the Q(Gui)Application exists: it pulls in the static "osmesa"
// platform plugin and, when nothing says otherwise (QT_QPA_PLATFORM unset and no
// DISPLAY or WAYLAND_DISPLAY), selects it. An explicit QT_QPA_PLATFORM or
// "-platform <name>" argument always wins.
void selectPlatformForHeadlessUse();

} // namespace shadowlab
