#pragma once

#include "DepthOnlyDraw.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "ShadowViews.h"

#include <QSize>

#include <optional>
#include <vector>

namespace shadowlab {

// The depth range of what the camera sees, for sample-distribution shadow maps
// (shadow.depth_fit = sdsm): every object the lit pass draws, depth only, at the frame's size,
// read back and reduced to the view depths of the nearest and farthest pixel drawn. It is the
// same frame's range at the same pixels, so the cascades fitted to it cover exactly the pixels
// then shaded. (At half the size the farthest pixel, where the ground meets the horizon, moved
// by far more than any padding: tst_LightTypes found 1.3 % of a close-up view beyond the last
// cascade.) The price is a read-back of the depth, which makes a GPU's pipeline wait; drawn
// again only when the scene, the camera or the size changed.
class VisibleDepthPass {
public:
    explicit VisibleDepthPass(GlFunctions* gl);

    // The range of the frame `camera` sees at `frameSize`: nullopt when nothing is drawn.
    // Leaves the framebuffer binding as it was. `draws` gets the draw calls issued (0 when kept).
    std::optional<VisibleDepthRange> ensure(const GpuScene& scene, int sceneGeneration, const CameraFrame& camera, QSize frameSize,
                                            int* draws = nullptr);

private:
    struct Key {
        int sceneGeneration = 0;
        glm::dmat4 viewProjection{1.0};
        QSize size;
        bool operator==(const Key&) const = default;
    };
    void allocate(QSize size);
    int draw(const GpuScene& scene, const CameraFrame& camera);

    GlFunctions* m_gl;
    DepthOnlyDraw m_draw;               // cut-outs through their masks: the eye sees through them
    GlTexture m_depth;
    GlFramebuffer m_framebuffer;
    QSize m_size;
    std::vector<float> m_readback;
    std::optional<Key> m_key;
    std::optional<VisibleDepthRange> m_range;
};

} // namespace shadowlab
