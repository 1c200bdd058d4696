#pragma once

#include "GpuScene.h"
#include "LightMath.h"
#include "ShaderConstants.h"
#include "ShaderProgram.h"

#include <QSize>

#include <memory>
#include <optional>

namespace shadowlab {

// The casters as the camera sees them, for the lit pass's contact shadows (contact.enabled):
// the distance along the view of the nearest front faces and of the nearest back faces, in
// one RG32F texture the size of the frame, from two depth-tested passes. Between the two a
// point is inside a caster; behind both, the light passes behind it. Only casters are drawn,
// so a receiver that casts nothing never darkens the march, and cut-outs leave their holes out
// unless shadow.cutouts casts them whole (the march is a shadow too). Redrawn only when the
// scene, the camera, the frame's size or that setting changed.
class CameraDepthPass {
public:
    explicit CameraDepthPass(GlFunctions* gl);

    // Draws when the scene (its generation), `camera` or `size` changed since the last draw;
    // returns the draws issued (0 when kept). Leaves the framebuffer binding as it was.
    int ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera, QSize size, bool cutouts = true);
    // Red: front faces, green: back faces; world units along the view direction, nearest texel.
    GLuint texture() const { return m_texture.id(); }
    QSize size() const { return m_size; }

private:
    struct Key {
        int sceneGeneration = 0;
        glm::dmat4 viewProjection{1.0};
        QSize size;
        bool cutouts = true;
        bool operator==(const Key&) const = default;
    };
    void allocate(QSize size);
    struct Variant {
        Variant(GlFunctions* gl, const QStringList& defines);
        ShaderProgram program;
        GLint mvp, model, forward, alphaCutoff;
    };
    int draw(const GpuScene& scene, const CameraFrame& camera, GLenum culled, bool cutouts);

    GlFunctions* m_gl;
    Variant m_plain;
    std::unique_ptr<Variant> m_cutout;  // compiled for the first scene with cut-outs
    GlTexture m_texture;
    GlTexture m_depth;              // the depth test's own, per pass
    GlFramebuffer m_framebuffer;
    QSize m_size;
    std::optional<Key> m_key;
};

} // namespace shadowlab
