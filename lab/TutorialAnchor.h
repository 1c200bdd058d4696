#pragma once

#include "GlObject.h"
#include "LightMath.h"
#include "Settings.h"

#include <QOpenGLShaderProgram>
#include <QSize>

#include <memory>

namespace shadowlab {

// The configuration of a typical tutorial implementation of the scene of `s`: 3 x 3 PCF on a
// 1024 map, bias max(0.05 (1 - N.L), 0.005), the hand-set light volume, and a shadow pass every
// frame (bench --baseline): the report's tutorial row (tutorialAssignments), the rest of the
// bias at its defaults.
Settings tutorialSettings(Settings s);

// The anchor of `bench --anchor`: the frame of the LearnOpenGL 3.1.3 shadow-mapping tutorial as
// its program draws it, in plain OpenGL 3.3 and none of ShadowLab's code, so ShadowLab's frame
// can be held against a classic implementation rather than against its own shader in the
// tutorial's settings (bench --baseline). Written for this comparison after the tutorial:
// - its scene: a 50 x 50 plane at y = -0.5 and three cubes, one textured material;
// - its light at (-2, 4, -1) toward the origin, ortho -10..10, near 1, far 7.5;
// - a 1024 x 1024 GL_DEPTH_COMPONENT map, nearest, clamped to a border of 1, drawn every frame
//   with no culling and no offset;
// - its lit pass: Blinn-Phong with pow(, 64), the normal matrix per vertex, a 3 x 3 PCF of
//   nine texture() reads and compares, bias max(0.05 (1 - N.L), 0.005), lit beyond the far plane;
// - its clears: the window's colour and depth before the shadow pass and twice after it;
// - its swap: glFinish here, into a window-like target (RGBA8, 24-bit depth, 8-bit stencil).
// The camera and the size are the caller's, so both programs draw the same pixels.
class TutorialAnchor {
public:
    // Needs a current 3.3 core context; throws RenderError where a shader does not build.
    TutorialAnchor(GlFunctions* gl, QSize size);

    // Draws one frame seen by `camera` and returns its wall time in ms, glFinish included.
    double timedFrame(const CameraFrame& camera);

private:
    void buildGeometry();
    void buildTextures();
    void drawScene(QOpenGLShaderProgram& program);

    GlFunctions* m_gl;
    QSize m_size;
    std::unique_ptr<QOpenGLShaderProgram> m_depthProgram, m_litProgram;
    GlVertexArray m_planeArray, m_cubeArray;
    GlBuffer m_planeVertices, m_cubeVertices;
    GlTexture m_wood, m_depthMap, m_windowColour, m_windowDepth;
    GlFramebuffer m_depthFramebuffer, m_window;
};

} // namespace shadowlab
