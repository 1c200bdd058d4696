#pragma once

#include "Renderer.h"

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>

#include <memory>

namespace shadowlab {

// A Renderer on its own offscreen context and framebuffer, for the command line and the
// tests. Needs a Q(Gui)Application; throws RenderError when no 3.3 core context can be made.
class HeadlessRenderer {
public:
    HeadlessRenderer();
    ~HeadlessRenderer();

    // Renders one frame of `settings` at `size` and returns it. Throws like Renderer::render().
    QImage renderScene(const Settings& settings, QSize size, TimingMode timing = TimingMode::Finish);
    // Renders the frame without reading it back (for benchmarks).
    void renderFrame(const Settings& settings, QSize size, TimingMode timing = TimingMode::Finish);
    // The shadow map of the last frame through the depth view's colour ramp, stretched over
    // the whole image (linearised for a perspective light).
    QImage renderDepthMap(QSize size);
    // The readable picture of it, as the explorer's pane draws it (DepthMapPicture): the map at
    // its volume's aspect in a `side` x `side` square, the outlines, and the legend below. The
    // image's text keys "map.size", "depth.nearest" and "depth.farthest" repeat the legend.
    QImage renderDepthPicture(int side);

    Renderer& renderer() { return *m_renderer; }
    GlFunctions* functions() const { return m_gl; }
    void makeCurrent();

private:
    RenderTarget targetOfSize(QSize size);

    QOffscreenSurface m_surface;
    QOpenGLContext m_context;
    GlFunctions* m_gl = nullptr;
    std::unique_ptr<QOpenGLFramebufferObject> m_framebuffer;
    std::unique_ptr<Renderer> m_renderer;
};

} // namespace shadowlab
