#pragma once

#include <QImage>
#include <QWidget>

namespace shadowlab {

// A magnifier over a scene view: the pixels around the pointer, each drawn as a block
// kZoom screen pixels wide, with the one under the pointer framed and its colour written
// below. It paints from the view's last frame (SceneView reads it back while the loupe is
// on), so moving the pointer redraws the loupe alone, never the scene.
class Loupe : public QWidget {
    Q_OBJECT

public:
    static constexpr int kRadius = 10;      // pixels each side of the one under the pointer
    static constexpr int kZoom = 8;

    explicit Loupe(QWidget* view);

    // Shows the pixels of `frame` (the view's framebuffer, device pixels) around `pointer`
    // (widget coordinates), placed beside the pointer inside the view.
    void showAt(const QPoint& pointer, const QImage& frame, double devicePixelRatio);
    // The pixel it magnifies in the middle, in device pixels of the frame.
    QPoint centre() const { return m_centre; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QImage m_region;
    QPoint m_centre;
};

} // namespace shadowlab
