#pragma once

#include <QStringList>

namespace shadowlab {

// The built-in scene presets, by name: the values of the `scene` key. Each is a resource file of
// the scene library, kScenePresetFolder/NAME.json (resources/scenes/ in the source), that lists its
// shapes (or names its generator) and its settings; adding a preset is adding a file. The scene
// library builds each (buildScene(), presetSettings()); tst_Scene checks that every name builds.
inline constexpr const char* kScenePresetFolder = ":/scenes";
const QStringList& sceneNames();

// The city preset takes its building count in its name: "city" (kCityBuildings) or "city:N"
// with N in [1, kMaxCityBuildings]; and its traffic after a plus: "city+V" or "city:N+V", V
// vehicles in [0, kMaxCityVehicles] driving its streets.
inline constexpr int kCityBuildings = 2000;
inline constexpr int kMaxCityBuildings = 20000;
inline constexpr int kMaxCityVehicles = 5000;
// The buildings of a city name, 0 for any other name (-1: a city name with a bad count).
int cityBuildingCount(const QString& name);
// The vehicles of a city name (0 without a plus; -1 for a bad count or not a city).
int cityVehicleCount(const QString& name);
// A preset's name: one of sceneNames() or a city with a building count.
bool isPresetName(const QString& name);

} // namespace shadowlab
