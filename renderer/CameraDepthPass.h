#pragma once

#include "GpuScene.h"
#include "LightMath.h"
#include "ShaderProgram.h"

#include <QSize>

#include <optional>

namespace shadowlab {

// The casters' depth as the camera sees them, for the lit pass's contact shadows
// (contact.enabled): two depth-only passes into textures the size of the frame, the nearest
// front faces and the nearest back faces. Between the two a point is inside a caster; behind
// both, the light passes behind it. Only casters are drawn, so a receiver that casts nothing
// never darkens the march. Redrawn only when the scene, the camera or the frame's size changed.
class CameraDepthPass {
public:
    explicit CameraDepthPass(GlFunctions* gl);

    // Draws when the scene (its generation), `camera` or `size` changed since the last draw;
    // returns the draws issued (0 when kept). Leaves the framebuffer binding as it was.
    int ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera, QSize size);
    // Window depth in [0, 1] (GL_DEPTH_COMPONENT32F, nearest), 1 where no caster is: of the
    // front faces, and of the back faces.
    GLuint frontTexture() const { return m_front.texture.id(); }
    GLuint backTexture() const { return m_back.texture.id(); }
    QSize size() const { return m_size; }

private:
    struct Key {
        int sceneGeneration = 0;
        glm::dmat4 viewProjection{1.0};
        QSize size;
        bool operator==(const Key&) const = default;
    };
    struct Layer {
        GlTexture texture;
        GlFramebuffer framebuffer;
    };
    void allocate(Layer& layer, QSize size, const char* faces);
    int draw(const Layer& layer, const GpuScene& scene, const CameraFrame& camera, GLenum culled);

    GlFunctions* m_gl;
    ShaderProgram m_program;
    GLint m_mvpLocation;
    Layer m_front;
    Layer m_back;
    QSize m_size;
    std::optional<Key> m_key;
};

} // namespace shadowlab
