#pragma once

namespace shadowlab {

// Process-wide set-up shared by the explorer, the command line and the tests; call before the
// Q(Gui)Application exists: the headless platform when there is no display, a 3.3 core
// default surface format, and shared contexts so every view samples the same shadow map.
void configureApplication();

} // namespace shadowlab
