#include "HeadlessBackingStore.h"

#include "HeadlessWindow.h"

#include <QtGui/QPainter>
#include <QtGui/QWindow>

// Exported by QtGui (qbackingstore.cpp) for exactly this purpose.
extern void qt_scrollRectInImage(QImage &img, const QRect &rect, const QPoint &offset);

namespace shadowlab {

HeadlessBackingStore::HeadlessBackingStore(QWindow *window)
    : QPlatformBackingStore(window)
{
}

QPaintDevice *HeadlessBackingStore::paintDevice()
{
    return &m_image;
}

void HeadlessBackingStore::flush(QWindow *window, const QRegion &region, const QPoint &offset)
{
    if (auto *platformWindow = static_cast<HeadlessWindow *>(window->handle()))
        platformWindow->presentImage(m_image, region, offset);
}

void HeadlessBackingStore::resize(const QSize &size, const QRegion &staticContents)
{
    Q_UNUSED(staticContents);
    const QImage::Format format =
            window()->format().hasAlpha() ? QImage::Format_ARGB32_Premultiplied : QImage::Format_RGB32;
    if (m_image.size() != size || m_image.format() != format)
        m_image = QImage(size, format);
}

bool HeadlessBackingStore::scroll(const QRegion &area, int dx, int dy)
{
    if (m_image.isNull())
        return false;
    qt_scrollRectInImage(m_image, area.boundingRect(), QPoint(dx, dy));
    return true;
}

void HeadlessBackingStore::beginPaint(const QRegion &region)
{
    // Translucent windows expect repainted areas to start out transparent.
    if (!m_image.hasAlphaChannel())
        return;
    QPainter painter(&m_image);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    for (const QRect &rect : region)
        painter.fillRect(rect, Qt::transparent);
}

QImage HeadlessBackingStore::toImage() const
{
    return m_image;
}

} // namespace shadowlab
