#pragma once

#include "Scene.h"

#include <QImage>

namespace shadowlab {

// Diffuse textures generated in code (no third-party images): a two-tone checker for
// floors and a wood-like ring pattern for objects. RGBA8888, `size` x `size`.
QImage makeProceduralTexture(TextureKind kind, int size = 256);

} // namespace shadowlab
