#pragma once

#include "Scene.h"

#include <QJsonArray>
#include <QString>

namespace shadowlab {

// Primitive shapes, the "shapes" of a scene file and of the built-in presets (resources/scenes/):
//
//   { "shape": "cube",             // cube, pyramid, sphere, torus, plane, card, or ground
//     "name": "high cube",         // optional; "cube 2" when left out
//     "position": [0, 1.5, 0],
//     "rotation": [0, 90, 0],      // degrees about x, y, z, or {"angle": 60, "axis": [1, 0, 1]}
//     "scale": 0.5,                // or [x, y, z], each > 0; a cube and a pyramid span -1..1
//     "texture": "wood",           // wood, checker or flat
//     "colour": [1, 1, 1],         // base colour, linear RGB in [0, 1]
//     "casts": true, "receives": true,
//     "major": 1, "minor": 0.35, "segments": 64, "sides": 24,   // torus
//     "rings": 16,                 // sphere, with "segments"
//     "size": 25, "tiles": 25,     // plane and ground: half-size and texture repeats
//     "height": 0 }                // ground: a checker plane at this height the camera stays above
//
// Shapes of the same kind and parameters share one mesh. Returns whether every shape that casts
// is closed (a plane or a card is not; the ground below everything does not count), so that the
// shadow pass may cull front faces. Throws SceneFileError naming `path`, the shape (shapes[i]),
// what is wrong and what is allowed.
bool appendShapes(Scene& scene, const QJsonArray& shapes, const QString& path);

} // namespace shadowlab
