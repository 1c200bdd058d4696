#pragma once

#include <qpa/qplatformscreen.h>

namespace shadowlab {

// A fixed 1920x1080 screen at 96 dpi, so layouts and font sizes match a common
// desktop. Grabbing shows what windows last presented (raster flush or GL swap).
class HeadlessScreen : public QPlatformScreen
{
public:
    QRect geometry() const override;
    int depth() const override;
    QImage::Format format() const override;
    QSizeF physicalSize() const override;
    QDpi logicalDpi() const override;
    QDpi logicalBaseDpi() const override;
    QString name() const override;
    QPixmap grabWindow(WId window, int x, int y, int width, int height) const override;
};

} // namespace shadowlab
