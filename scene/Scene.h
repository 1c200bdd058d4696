#pragma once

#include <optional>

#include "Bounds.h"
#include "Mesh.h"

#include <glm/mat4x4.hpp>

#include <QString>

#include <vector>

namespace shadowlab {

enum class TextureKind { Checker, Wood };

struct SceneObject {
    QString name;
    int mesh = 0;                       // index into Scene::meshes
    glm::dmat4 model{1.0};              // object to world
    TextureKind texture = TextureKind::Wood;
    bool castsShadow = true;
};

// Meshes in object space and their placements; what the renderer and the ray tracer share.
struct Scene {
    QString name;
    std::vector<Mesh> meshes;
    std::vector<SceneObject> objects;
    std::optional<double> groundHeight; // y of a ground plane the camera should stay above, if any

    Bounds worldBounds(const SceneObject& object) const;
    Bounds casterBounds() const;        // empty when nothing casts
    Bounds bounds() const;              // everything
};

} // namespace shadowlab
