#pragma once

#include <optional>

#include "Bounds.h"
#include "Mesh.h"
#include "Motion.h"

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
    // A cut-out material (glTF alphaMode MASK): where the base-colour alpha (the texture's alpha
    // times baseAlpha) is below alphaCutoff the surface is not there, for the light as for the
    // eye (leaves, fences). 0: opaque, drawn whole whatever its alpha.
    float alphaCutoff = 0.0f;           // [0, 1]
    float baseAlpha = 1.0f;             // the base colour's alpha, [0, 1]
    // How it moves: its placement at time t is motion->at(t), and `model` is that at the scene's
    // time (0 as loaded). None: a static object, which nothing about time touches.
    std::optional<Motion> motion{};
};

// Whether the object is a cut-out (a mask drawn and traced through its holes).
inline bool isCutout(const SceneObject& object) { return object.alphaCutoff > 0.0f; }
// The texture alpha below which a cut-out object is absent: alphaCutoff / baseAlpha, so a
// shader or tracer compares the texture's alpha alone (above 1 when nothing of it is there);
// 0 for an opaque object.
float textureAlphaCutoff(const SceneObject& object);

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

    // World bounds of the object; of everywhere it goes, for one that moves (at the samples of
    // Motion::sweptBounds, unpadded).
    Bounds worldBounds(const SceneObject& object) const;
    Bounds casterBounds() const;        // empty when nothing casts
    Bounds bounds() const;              // everything
    bool hasCutouts() const;            // any cut-out object (isCutout)
    // Everything but the checkered ground plane a preset or a loaded model stands on: the size
    // cameras, lights and sliders follow (the whole scene when there is nothing else).
    Bounds modelBounds() const;
    // Whether any object moves.
    bool moves() const;
    // The longest cycle of any moving object's motion, in seconds; 0 for a still scene.
    double clipLength() const;
    // Every moving object's model set to its placement at time `t` seconds; the indices of those
    // that moved (none for a still scene, whatever t).
    std::vector<std::size_t> poseAt(double t);
};

} // namespace shadowlab
