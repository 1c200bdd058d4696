#pragma once

#include "GpuScene.h"
#include "LightMath.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

namespace shadowlab {

// Shadow pass: renders the casters' depth from the light into the shadow map. Casters
// entirely outside the light's volume are not drawn. Options from BiasSettings: front-face
// culling (only back faces reach the map) and glPolygonOffset.
class DepthPass {
public:
    explicit DepthPass(GlFunctions* gl);

    // Returns the number of draw calls issued.
    int render(const GpuScene& scene, const LightFrame& light, const BiasSettings& bias, const ShadowMap& map);

private:
    GlFunctions* m_gl;
    ShaderProgram m_program;
    GLint m_mvpLocation;
};

} // namespace shadowlab
