#include "SceneSupply.h"

#include "SceneLoader.h"
#include "SceneNames.h"

namespace shadowlab {

void supplyScene(Renderer& renderer, const Settings& settings)
{
    if (renderer.needsSceneFile(settings)) {
        renderer.setSceneFile(settings.scene, loadSceneFile(settings.scene));
        return;
    }
    const std::shared_ptr<const Scene> latest = isPresetName(settings.scene) ? nullptr : loadedSceneFile(settings.scene);
    if (latest && renderer.holdsOlderSceneFile(settings.scene, latest))
        renderer.setSceneFile(settings.scene, latest);
}

} // namespace shadowlab
