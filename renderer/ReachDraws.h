#pragma once

#include "GlObject.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "ShaderProgram.h"
#include "ShadowReach.h"

#include <QRect>

#include <memory>
#include <utility>
#include <vector>

namespace shadowlab {

// The shadow reach in the lit pass, a software rasteriser's optimisation
// (RasteriserTuning::skipsOutOfReach): which receivers look the shadow up, in what order, and
// the stencil mask of the reach over those that straddle it. Receivers out of reach are
// shaded without a lookup; those that straddle it are drawn twice, with the lookup inside the
// mask and without it outside, each half scissored to its rectangles on screen. Without a
// reach every receiver in view looks up, nearest first. The frame is the same either way.
class ReachDraws {
public:
    explicit ReachDraws(GlFunctions* gl);

    // (distance to the camera, draw item), nearest first.
    using Order = std::vector<std::pair<double, std::size_t>>;

    // Sorts the receivers `camera` sees by `reach` (null, or no shadows: every one looks up).
    // A mask is drawn only where `stencil` (the target has stencil bits) and it pays.
    void sort(const GpuScene& scene, const CameraFrame& camera, bool shadows, const ShadowReach* reach, bool stencil);
    const Order& lookup() const { return m_lookup; }                // look up everywhere
    const Order& maskedLookup() const { return m_maskedLookup; }    // look up inside the mask
    const Order& maskedPlain() const { return m_maskedPlain; }      // shaded without a lookup outside it
    const Order& plain() const { return m_plain; }                  // shaded without a lookup everywhere

    // What the last sort decided: receivers drawn with and without a lookup, and whether a
    // mask is drawn.
    struct Use {
        int lookupDraws = 0;
        int plainDraws = 0;
        bool masked = false;
    };
    const Use& use() const { return m_use; }

    // Marks the reach's mask (ShadowReach::mask) in the bound target's stencil buffer (1
    // inside), colour and depth untouched, and returns the rectangles the lookups' draws are
    // scissored to; none without a mask. Leaves the pass state to the caller.
    std::vector<QRect> drawMask(const CameraFrame& camera, QSize targetSize);

private:
    // Uploads the mask's triangles when the reach changed.
    void uploadMask();

    GlFunctions* m_gl;
    const ShadowReach* m_reach = nullptr;
    Order m_order;                      // every receiver in view, reused per frame
    Order m_lookup, m_maskedLookup, m_maskedPlain, m_plain;
    Use m_use;
    // The mask's program (the shadow pass's: positions through one matrix, no colour) and its
    // boxes, uploaded when the reach changes.
    std::unique_ptr<ShaderProgram> m_program;
    GLint m_matrix = -1;
    GlVertexArray m_vertexArray;
    GlBuffer m_vertices;
    GLsizei m_vertexCount = 0;
    int m_generation = -1;              // the reach the uploaded boxes were made from
    glm::dvec3 m_origin{0.0};           // the boxes' vertices are relative to it
};

} // namespace shadowlab
