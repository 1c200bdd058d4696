#pragma once

#include <QString>

namespace shadowlab {

// Who holds the copyright and under which licence ShadowLab is given (LICENSE): `--version`, the
// About box, the metainfo and the Debian package's copyright file say the same.
inline constexpr const char* kCopyrightLine = "Copyright (c) 2026 The ShadowLab developers";
inline constexpr const char* kLicenceName = "MIT";

// What `--version` prints: the version, the copyright and the licence, as GNU programs do.
QString versionText();

// Process-wide set-up shared by the explorer, the command line and the tests; call before the
// Q(Gui)Application exists: the headless platform when there is no display, a 3.3 core
// default surface format, and shared contexts so every view samples the same shadow map.
void configureApplication();

} // namespace shadowlab
