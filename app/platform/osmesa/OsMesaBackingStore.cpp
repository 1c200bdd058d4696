#include "OsMesaBackingStore.h"

#include "OsMesaWindow.h"

#include <QtGui/QPainter>
#include <QtGui/QWindow>

// Exported by QtGui (qbackingstore.cpp) for exactly this purpose.
extern void qt_scrollRectInImage(QImage &img, const QRect &rect, const QPoint &offset);

namespace shadowlab {

OsMesaBackingStore::OsMesaBackingStore(QWindow *window)
    : QPlatformBackingStore(window)
{
}

QPaintDevice *OsMesaBackingStore::paintDevice()
{
    return &m_image;
}

void OsMesaBackingStore::flush(QWindow *window, const QRegion &region, const QPoint &offset)
{
    if (auto *platformWindow = static_cast<OsMesaWindow *>(window->handle()))
        platformWindow->presentImage(m_image, region, offset);
}

void OsMesaBackingStore::resize(const QSize &size, const QRegion &staticContents)
{
    Q_UNUSED(staticContents);
    const QImage::Format format =
            window()->format().hasAlpha() ? QImage::Format_ARGB32_Premultiplied : QImage::Format_RGB32;
    if (m_image.size() != size || m_image.format() != format)
        m_image = QImage(size, format);
}

bool OsMesaBackingStore::scroll(const QRegion &area, int dx, int dy)
{
    if (m_image.isNull())
        return false;
    qt_scrollRectInImage(m_image, area.boundingRect(), QPoint(dx, dy));
    return true;
}

void OsMesaBackingStore::beginPaint(const QRegion &region)
{
    // Translucent windows expect repainted areas to start out transparent.
    if (!m_image.hasAlphaChannel())
        return;
    QPainter painter(&m_image);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    for (const QRect &rect : region)
        painter.fillRect(rect, Qt::transparent);
}

QImage OsMesaBackingStore::toImage() const
{
    return m_image;
}

} // namespace shadowlab
