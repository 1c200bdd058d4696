#pragma once

#include <optional>

#include "Bounds.h"
#include "Mesh.h"

#include <glm/mat4x4.hpp>

#include <QByteArray>
#include <QImage>
#include <QString>
#include <QStringList>

#include <vector>

namespace shadowlab {

// What colours an object: a procedural texture (presets), a flat base colour, or one of the
// scene's images (an imported base-colour texture), each multiplied by the base colour.
enum class TextureKind { Checker, Wood, Flat, Image };

struct SceneObject {
    QString name;
    int mesh = 0;                       // index into Scene::meshes
    glm::dmat4 model{1.0};              // object to world
    TextureKind texture = TextureKind::Wood;
    bool castsShadow = true;
    bool receivesShadow = true;         // false: always lit, and left out of accuracy measurements
    glm::vec3 baseColour{1.0f};         // linear RGB in 0..1
    int image = -1;                     // index into Scene::images when texture is Image
};

// Meshes in object space and their placements; what the renderer and the ray tracer share.
struct Scene {
    QString name;
    std::vector<Mesh> meshes;
    std::vector<SceneObject> objects;
    std::optional<double> groundHeight; // y of a ground plane the camera should stay above, if any
    std::vector<QImage> images;         // base-colour textures of imported materials, RGBA8888
    // What a reference traced for this scene may be cached under: the preset's name, or a hash
    // of a loaded file's bytes (and of every file it names), so a renamed copy shares a trace
    // and an edited file does not.
    QByteArray identity;
    QStringList warnings;               // what the import changed or ignored, said once on load

    Bounds worldBounds(const SceneObject& object) const;
    Bounds casterBounds() const;        // empty when nothing casts
    Bounds bounds() const;              // everything
    // Everything but the checkered ground plane a preset or a loaded model stands on: the size
    // cameras, lights and sliders follow (the whole scene when there is nothing else).
    Bounds modelBounds() const;
};

} // namespace shadowlab
