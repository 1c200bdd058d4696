#pragma once

#include "Scene.h"

#include <QStringList>

#include <cstddef>
#include <functional>

namespace shadowlab {

// Limits on what a model may be, stated once: larger files are refused before they are read.
constexpr qint64 kMaxModelFileBytes = qint64(1) << 30;          // 1 GiB
constexpr std::size_t kMaxModelTriangles = 10'000'000;
// A model whose bounding-box diagonal lies outside this range (in its own units) is scaled
// uniformly to kNormalisedModelSize, with a warning: biases, light radii and float depth all
// assume sizes a person models in, and 1e-6 or 1e6 units would give acne or NaN instead.
constexpr double kMinModelSize = 1e-3;
constexpr double kMaxModelSize = 1e5;
constexpr double kNormalisedModelSize = 10.0;
// Meshes above this many triangles are split into spatially compact pieces, so the shadow
// and lit passes can skip the pieces outside the light volume or the view.
constexpr std::size_t kMeshChunkTriangles = 1 << 16;
// The most keys a node animation keeps per object: a denser one (motion capture at 120 Hz for
// minutes) is taken at this many even times instead, with a warning.
constexpr std::size_t kMaxMotionKeys = 4096;

// Reads a model through Assimp (OBJ, glTF 2, PLY, STL, COLLADA, FBX and whatever else the
// installed Assimp reads): triangulated, normals generated where missing, node transforms
// applied as object placements, the first animation's node channels as their motions (whole
// nodes move; skins are drawn in their bind pose), base colour and base-colour texture kept. Throws
// SceneFileError naming the file, the problem and what to do about it. The result has no
// ground plane, light or camera; Scene::identity is a hash of the file's bytes. `progress`
// hears Assimp's progress through the read (0..1).
// This runs Assimp in the calling process: everything else reads files through
// importModelIsolated() (IsolatedImport.h), which runs this in the import worker.
Scene importModel(const QString& path, const std::function<void(double)>& progress = {});

// Lower-case file suffixes (no dot) the installed Assimp can read.
QStringList modelSuffixes();

} // namespace shadowlab
