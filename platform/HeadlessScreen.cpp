#include "HeadlessScreen.h"

#include "HeadlessWindow.h"

#include <QtGui/QGuiApplication>
#include <QtGui/QPainter>
#include <QtGui/QPixmap>
#include <QtGui/QWindow>

namespace shadowlab {

namespace {
constexpr QSize screenSize(1920, 1080);
constexpr qreal dotsPerInch = 96.0;
constexpr qreal millimetresPerInch = 25.4;

// Qt's convention: a negative width or height means "to the right/bottom edge".
QRect grabRect(const QSize &available, int x, int y, int width, int height)
{
    return QRect(x, y, width < 0 ? available.width() - x : width, height < 0 ? available.height() - y : height);
}
} // namespace

QRect HeadlessScreen::geometry() const
{
    return QRect(QPoint(0, 0), screenSize);
}

int HeadlessScreen::depth() const
{
    return 32;
}

QImage::Format HeadlessScreen::format() const
{
    return QImage::Format_RGB32;
}

QSizeF HeadlessScreen::physicalSize() const
{
    return QSizeF(screenSize) * (millimetresPerInch / dotsPerInch);
}

QDpi HeadlessScreen::logicalDpi() const
{
    return QDpi(dotsPerInch, dotsPerInch);
}

QDpi HeadlessScreen::logicalBaseDpi() const
{
    return QDpi(dotsPerInch, dotsPerInch);
}

QString HeadlessScreen::name() const
{
    return QStringLiteral("headless");
}

QPixmap HeadlessScreen::grabWindow(WId window, int x, int y, int width, int height) const
{
    if (window) {
        const QWindowList windows = QGuiApplication::allWindows();
        for (QWindow *candidate : windows) {
            auto *platformWindow = static_cast<HeadlessWindow *>(candidate->handle());
            if (platformWindow && platformWindow->winId() == window) {
                const QImage presented = platformWindow->presentedImage();
                return QPixmap::fromImage(presented.copy(grabRect(presented.size(), x, y, width, height)));
            }
        }
        return QPixmap();
    }

    // Window 0 is the whole screen: stack what every visible top-level presented.
    const QRect area = grabRect(screenSize, x, y, width, height);
    QImage image(area.size(), QImage::Format_RGB32);
    image.fill(Qt::black);
    QPainter painter(&image);
    painter.translate(-area.topLeft());
    const QWindowList windows = QGuiApplication::topLevelWindows();
    for (QWindow *candidate : windows) {
        const auto *platformWindow = static_cast<const HeadlessWindow *>(candidate->handle());
        if (platformWindow && candidate->isExposed())
            painter.drawImage(platformWindow->geometry().topLeft(), platformWindow->presentedImage());
    }
    painter.end();
    return QPixmap::fromImage(image);
}

} // namespace shadowlab
