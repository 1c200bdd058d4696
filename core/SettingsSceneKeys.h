#pragma once

#include "SettingKinds.h"

#include <QLatin1String>

namespace shadowlab::settings {

// `scene`: a preset, a city of N buildings and V vehicles, or a model or scene file.
Entry sceneKey(const SettingPresentation& look);
// A list of the scene's objects (ObjectSwitches::*list), names or #i, in the dock's `group`.
Entry objectSwitchKey(const char* key, const char* help, const QString& label, QLatin1String group, QStringList ObjectSwitches::*list);

} // namespace shadowlab::settings
