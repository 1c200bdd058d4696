#pragma once

namespace shadowlab {

// The largest side, in texels or pixels, of a shadow map or an image any setting or option
// allows; the driver's GL_MAX_TEXTURE_SIZE may allow less (checked when the map is made).
constexpr int kMaxImageSide = 16384;

} // namespace shadowlab
