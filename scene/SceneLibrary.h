#pragma once

#include "Scene.h"
#include "SceneNames.h"
#include "Settings.h"

#include <QStringList>

#include <vector>

namespace shadowlab {

// Builds a preset's geometry, or loads the model or scene file `name` is a path of
// (SceneLoader.h); throws SettingsError (SceneFileError for files) when it cannot.
Scene buildScene(const QString& name);
// A preset's geometry (isPresetName(name)): built from the program's own resources, reading no
// file and starting no process. Throws SettingsError for a name that is not a preset.
Scene buildPresetScene(const QString& name);

// Default settings for a preset (the global defaults with the preset's light and camera) or
// for a model or scene file (derived from its bounds, then the file's own keys).
Settings presetSettings(const QString& name);

// The seed's lengths times this fit the scene `name`: 1 for a preset (each is in the seed's
// units), sceneLengthScale() of its models for a model or scene file. Throws like buildScene().
double sceneScale(const QString& name);

// How ObjectSwitches names each of `scene`'s objects: its name where that is its own (not
// empty, held by no other object, without a comma), else "#i" by its index.
QStringList objectTokens(const Scene& scene);
// `scene` with `switches` applied: the objects named stop casting or receiving. Throws a
// SettingsError naming objects.no_cast or objects.no_receive for a name or index the scene does
// not have, with the names it has.
void applyObjectSwitches(Scene& scene, const ObjectSwitches& switches);

// The camera the scene `name` opens with in a view of `aspect` (width / height): a preset's own;
// a model's or scene file's moved back along its line of sight, where needed, until the models'
// bounding sphere fits the narrower of the view's two angles, so a view taller than it is wide
// does not crop a model its file frames for 16:9. Throws like presetSettings().
CameraSettings presetCamera(const QString& name, double aspect);

// `side`'s settings on the scene whose settings are `scene` (its presetSettings(), or another
// side already on it): what belongs to the scene comes from there (the scene, its light and
// camera, its objects' switches, and the lengths in its world units: world-space bias, cascade distance, reference
// light size, and whether its meshes are closed enough to cull front faces); the techniques
// being compared stay. This is how a scene is shared by both sides of compare mode.
Settings movedToScene(const Settings& side, const Settings& scene);

// What a scene's references may be cached under: a preset's name, or "sha256:" and the hash
// of a loaded file's content (and of the files it names), so renaming a file keeps its cached
// traces and editing it does not. Throws like buildScene().
QString sceneIdentity(const QString& name);
// Whether the scene `name` (a preset, or a file loaded as buildScene() loads it) has cut-out
// objects; false for a name that does not load.
bool sceneHasCutouts(const QString& name);
// Whether the scene `name` has moving objects (its frames depend on scene.time); false for a
// name that does not load.
bool sceneMoves(const QString& name);

// A camera path from `start` (a scene's camera): `frames` cameras, each `step` world units
// along (sideways and a little forward, the view keeping its direction), for measuring what
// camera motion does to shadows (flicker, the cost of a moving camera).
std::vector<CameraSettings> cameraPath(const CameraSettings& start, int frames, double step);

} // namespace shadowlab
