#pragma once

#include "Scene.h"

#include <QImage>

namespace shadowlab {

// Diffuse textures generated in code (no third-party images): a two-tone checker for
// floors and a wood-like ring pattern for objects. RGBA8888, `size` x `size`.
QImage makeProceduralTexture(TextureKind kind, int size = 256);

// Cut-out textures for the foliage preset, RGBA8888 with alpha 255 where the surface is and 0
// where it is not (the colour there is the surface's, so filtering leaves no dark fringe).
// A cluster of leaves on a stem, the same for the same `seed`:
QImage makeLeafTexture(int seed, int size = 256);
// A garden trellis: two sets of diagonal slats crossing, tiling:
QImage makeTrellisTexture(int size = 256);

} // namespace shadowlab
