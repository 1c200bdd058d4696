#pragma once

#include "IsolatedImport.h"
#include "Scene.h"
#include "Settings.h"

#include <memory>

namespace shadowlab {

// Scenes the user brings: a model file (anything importModel() reads) or a scene file (.json):
//
//   { "models": [ { "file": "engine.glb",            // relative to the scene file
//                   "position": [0, 0, 0], "rotation": [0, 90, 0],   // degrees about x, y, z
//                   "scale": 1.0,                    // or [x, y, z]
//                   "casts": true, "receives": true } ],
//     "ground": true,                                // false, or the ground's height
//     "light.position": [..], "camera.target": [..], ...  // any key of `shadowlab settings`
//   }
//
// A model gets a ground plane under it, a camera framing it and a light from above at an
// angle, all from its bounds; a scene file may turn the ground off and set any key.
// Loads are cached by absolute path, size and modification time, so every command and view
// shares one import; models are read by the import worker under `control`'s limits
// (IsolatedImport.h). Throws SceneFileError naming the file, what is wrong and how to fix it.
std::shared_ptr<const Scene> loadSceneFile(const QString& path, const ImportControl& control = {});

// The last load of `path` in that cache, as it was read, without looking at the file (null:
// never loaded): a file read again after it changed on disk gives its new scene here.
std::shared_ptr<const Scene> loadedSceneFile(const QString& path);

// The settings a loaded scene starts with: defaults, the light, camera, bias and reference
// radius derived from its bounds, then the scene file's own keys. Throws like loadSceneFile().
Settings sceneFileSettings(const QString& path);

// How many of the seed's world units one of a model's is worth: its models' bounding radius over
// the seed's objects' (2.5). The lengths tuned on the seed (bias, the reference light, sweeps'
// light placements) are scaled by it for a model or scene file.
double sceneLengthScale(double modelRadius);

} // namespace shadowlab
