#pragma once

#include "Renderer.h"

namespace shadowlab {

// Hands `renderer` the scene of the model or scene file that settings.scene names, loaded
// before the frame (through SceneLoader's cache, which may start the import worker), where the
// renderer has not got it yet, or a newer load of the file it has (read again after it changed
// on disk): a frame itself reads no file and starts no process. A preset needs nothing. Throws
// what loadSceneFile() throws.
void supplyScene(Renderer& renderer, const Settings& settings);

} // namespace shadowlab
