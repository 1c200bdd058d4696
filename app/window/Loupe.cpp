#include "Loupe.h"

#include <QPainter>

#include <algorithm>

namespace shadowlab {

namespace {

constexpr int kSide = (2 * Loupe::kRadius + 1) * Loupe::kZoom;
constexpr int kCaption = 18;

} // namespace

Loupe::Loupe(QWidget* view) : QWidget(view)
{
    setObjectName(QStringLiteral("loupe"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setFixedSize(kSide + 2, kSide + 2 + kCaption);
    hide();
}

void Loupe::showAt(const QPoint& pointer, const QImage& frame, double devicePixelRatio)
{
    if (frame.isNull()) {
        hide();
        return;
    }
    m_centre = QPoint(int(pointer.x() * devicePixelRatio), int(pointer.y() * devicePixelRatio));
    const int n = 2 * kRadius + 1;
    // Outside the frame reads black: the loupe keeps its size at the view's edges.
    m_region = QImage(n, n, QImage::Format_RGB32);
    m_region.fill(Qt::black);
    QPainter copy(&m_region);
    copy.drawImage(QPoint(0, 0), frame, QRect(m_centre - QPoint(kRadius, kRadius), QSize(n, n)));
    copy.end();
    // Beside the pointer, down and right, flipped where it would leave the view.
    const QWidget* view = parentWidget();
    QPoint at = pointer + QPoint(24, 24);
    if (at.x() + width() > view->width())
        at.setX(pointer.x() - 24 - width());
    if (at.y() + height() > view->height())
        at.setY(pointer.y() - 24 - height());
    // A view narrower than both sides' room: inside it still, over the pointer if it must be.
    at.setX(std::clamp(at.x(), 0, std::max(0, view->width() - width())));
    at.setY(std::clamp(at.y(), 0, std::max(0, view->height() - height())));
    move(at);
    show();
    raise();
    update();
}

void Loupe::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), QColor(20, 22, 30));
    painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
    painter.drawImage(QRect(1, 1, kSide, kSide), m_region);
    // The pixel under the pointer, framed in both colours so it shows on any picture.
    const QRect middle(1 + kRadius * kZoom, 1 + kRadius * kZoom, kZoom, kZoom);
    painter.setPen(QPen(Qt::black, 1));
    painter.drawRect(middle.adjusted(-1, -1, 0, 0));
    painter.setPen(QPen(Qt::white, 1));
    painter.drawRect(middle.adjusted(-2, -2, 1, 1));
    painter.setPen(QColor(120, 126, 140));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    const QColor c = m_region.pixelColor(kRadius, kRadius);
    painter.setPen(QColor(225, 228, 235));
    painter.drawText(QRect(4, kSide + 2, kSide - 6, kCaption), Qt::AlignVCenter | Qt::AlignLeft,
                     tr("%1, %2  %3").arg(m_centre.x()).arg(m_centre.y()).arg(c.name()));
}

} // namespace shadowlab
