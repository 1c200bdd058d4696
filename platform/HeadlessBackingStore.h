#pragma once

#include <qpa/qplatformbackingstore.h>

#include <QtGui/QImage>

namespace shadowlab {

// Raster widgets paint into a plain QImage. A flush copies it into the window's
// presented image; with QRhi composition (QOpenGLWidget present) Qt uploads
// toImage() as a texture instead and the GL swap presents.
class HeadlessBackingStore : public QPlatformBackingStore
{
public:
    explicit HeadlessBackingStore(QWindow *window);

    QPaintDevice *paintDevice() override;
    void flush(QWindow *window, const QRegion &region, const QPoint &offset) override;
    void resize(const QSize &size, const QRegion &staticContents) override;
    bool scroll(const QRegion &area, int dx, int dy) override;
    void beginPaint(const QRegion &region) override;
    QImage toImage() const override;

private:
    QImage m_image;
};

} // namespace shadowlab
