#include "SceneSupply.h"

#include "SceneLoader.h"

namespace shadowlab {

void supplyScene(Renderer& renderer, const Settings& settings)
{
    if (renderer.needsSceneFile(settings))
        renderer.setSceneFile(settings.scene, loadSceneFile(settings.scene));
}

} // namespace shadowlab
