#include "Scene.h"

#include <algorithm>

namespace shadowlab {

Bounds Scene::worldBounds(const SceneObject& object) const
{
    Bounds local;
    for (const Vertex& v : meshes.at(std::size_t(object.mesh)).vertices)
        local.extend(glm::dvec3(v.position));
    // Where it goes at the sweep's samples, unpadded: a ground laid under the scene meets the
    // lowest pose, not half a sample's step below it.
    return object.motion ? object.motion->sweptBounds(local, false) : local.transformed(object.model);
}

bool Scene::moves() const
{
    return std::any_of(objects.begin(), objects.end(), [](const SceneObject& o) { return o.motion.has_value(); });
}

double Scene::clipLength() const
{
    double length = 0.0;
    for (const SceneObject& o : objects) {
        if (o.motion)
            length = std::max(length, o.motion->length());
    }
    return length;
}

std::vector<std::size_t> Scene::poseAt(double t)
{
    std::vector<std::size_t> moved;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        SceneObject& o = objects[i];
        if (!o.motion)
            continue;
        const glm::dmat4 model = o.motion->at(t);
        if (model != o.model) {
            o.model = model;
            moved.push_back(i);
        }
    }
    return moved;
}

Bounds Scene::casterBounds() const
{
    Bounds b;
    for (const SceneObject& o : objects) {
        if (o.castsShadow)
            b.extend(worldBounds(o));
    }
    return b;
}

Bounds Scene::modelBounds() const
{
    Bounds b;
    for (const SceneObject& o : objects) {
        if (o.name != u"ground" || o.texture != TextureKind::Checker)
            b.extend(worldBounds(o));
    }
    return b.isEmpty() ? bounds() : b;
}

Bounds Scene::bounds() const
{
    Bounds b;
    for (const SceneObject& o : objects)
        b.extend(worldBounds(o));
    return b;
}

bool Scene::hasCutouts() const
{
    return std::any_of(objects.begin(), objects.end(), [](const SceneObject& o) { return isCutout(o); });
}

float textureAlphaCutoff(const SceneObject& object)
{
    if (!isCutout(object))
        return 0.0f;
    // A base alpha of 0 leaves nothing: a cut-off no texture alpha reaches.
    return object.baseAlpha > 0.0f ? object.alphaCutoff / object.baseAlpha : 2.0f;
}

} // namespace shadowlab
