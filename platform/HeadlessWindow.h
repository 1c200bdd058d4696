#pragma once

#include <qpa/qplatformwindow.h>

#include <QtGui/QImage>

#include <cstdint>
#include <vector>

namespace shadowlab {

// A window that exists only in memory. It owns
//  - with OSMesa, the GL render buffer OSMesa draws into when a context is current on the
//    window (RGBA bytes, bottom row first, sized to the window; reallocated lazily when the
//    window size changed, at the next makeCurrent; EGL contexts keep a framebuffer object
//    per window instead), and
//  - the presented image, top row first, updated by swapBuffers() and by raster
//    backing-store flushes: what a screen grab shows.
class HeadlessWindow : public QPlatformWindow
{
public:
    explicit HeadlessWindow(QWindow *window);
    ~HeadlessWindow() override;

    void setGeometry(const QRect &rect) override;
    void setVisible(bool visible) override;
    void setWindowState(Qt::WindowStates state) override;
    void requestActivateWindow() override;
    WId winId() const override;
    QSurfaceFormat format() const override;
    // No window manager to tell: size hints have nowhere to go (and the default warns).
    void propagateSizeHints() override {}

    struct RenderBuffer
    {
        void *pixels = nullptr;
        QSize size;
    };
    // The buffer a GL context should draw into, resized to the window first if needed.
    RenderBuffer renderBuffer();
    // The buffer as it is, for checking what a context is bound to.
    const void *renderPixels() const;
    // Copies the finished GL frame (render buffer) into the presented image.
    void presentRenderBuffer();
    // Shows a finished GL frame (top row first) read back from a framebuffer object.
    void presentFrame(const QImage &frame);
    // Copies the given area of a raster backing store into the presented image.
    void presentImage(const QImage &source, const QRegion &region, const QPoint &offset);
    QImage presentedImage() const;

    // False once the window with this id is destroyed (GUI thread only).
    static bool isAlive(WId id);

private:
    void reportExposure();

    std::vector<std::uint32_t> m_renderPixels; // one RGBA quadruple per pixel
    QSize m_renderSize;
    QImage m_presented;
    QRect m_normalGeometry;
    WId m_winId;
    bool m_visible = false;
};

} // namespace shadowlab
