#include "HeadlessWindow.h"

#ifdef SHADOWLAB_HAVE_OSMESA
#include "OsMesaOpenGLContext.h"
#endif

#include <QtCore/QSet>
#include <QtGui/QPainter>
#include <QtGui/QWindow>
#include <qpa/qplatformscreen.h>
#include <qpa/qwindowsysteminterface.h>

#include <atomic>

namespace shadowlab {

namespace {
constexpr int defaultWidth = 640;
constexpr int defaultHeight = 480;

WId nextWindowId()
{
    static std::atomic<WId> counter{ 0 };
    return ++counter;
}

QSet<WId> &liveWindows()
{
    static QSet<WId> ids;
    return ids;
}
} // namespace

HeadlessWindow::HeadlessWindow(QWindow *window)
    : QPlatformWindow(window)
    , m_winId(nextWindowId())
{
    liveWindows().insert(m_winId);
    // Gives windows created without a size the usual default size and placement.
    const QRect initial = initialGeometry(window, windowGeometry(), defaultWidth, defaultHeight);
    if (window->windowStates() & (Qt::WindowFullScreen | Qt::WindowMaximized))
        setWindowState(window->windowStates());
    else
        setGeometry(initial);
}

HeadlessWindow::~HeadlessWindow()
{
    liveWindows().remove(m_winId);
#ifdef SHADOWLAB_HAVE_OSMESA
    // OSMesa writes into the bound buffer whenever the context flushes, including
    // when it is later released or destroyed; never leave it pointing at freed memory.
    OsMesaOpenGLContext::releaseIfDrawingTo(m_renderPixels.data());
#endif
}

bool HeadlessWindow::isAlive(WId id)
{
    return liveWindows().contains(id);
}

void HeadlessWindow::setGeometry(const QRect &rect)
{
    // OSMesa needs at least 1x1 to make a context current, so empty windows get one pixel.
    const QRect adjusted(rect.topLeft(), rect.size().expandedTo(QSize(1, 1)));
    QPlatformWindow::setGeometry(adjusted);
    if (!(window()->windowStates() & (Qt::WindowFullScreen | Qt::WindowMaximized)))
        m_normalGeometry = adjusted;

    // There is no window manager to confirm the request, so confirm it ourselves;
    // QWindow only updates its geometry from this notification.
    QWindowSystemInterface::handleGeometryChange(window(), adjusted);
    if (m_visible)
        reportExposure();
}

void HeadlessWindow::setVisible(bool visible)
{
    if (visible == m_visible)
        return;
    m_visible = visible;

    if (!visible) {
        QWindowSystemInterface::handleExposeEvent(window(), QRegion());
        return;
    }
    // Showing a top-level activates it, as a window manager would; widgets and
    // QTest::qWaitForWindowActive rely on it.
    if (window()->isTopLevel() && window()->type() != Qt::ToolTip)
        QWindowSystemInterface::handleWindowActivated(window(), Qt::ActiveWindowFocusReason);
    reportExposure();
}

void HeadlessWindow::setWindowState(Qt::WindowStates state)
{
    QRect target = m_normalGeometry;
    if (state & Qt::WindowFullScreen)
        target = screen()->geometry();
    else if (state & Qt::WindowMaximized)
        target = screen()->availableGeometry();

    if (!(state & Qt::WindowMinimized)) {
        QPlatformWindow::setGeometry(target.isValid() ? target : geometry());
        QWindowSystemInterface::handleGeometryChange(window(), QPlatformWindow::geometry());
        if (m_visible)
            reportExposure();
    }
    QWindowSystemInterface::handleWindowStateChanged(window(), state);
}

void HeadlessWindow::requestActivateWindow()
{
    if (m_visible)
        QWindowSystemInterface::handleWindowActivated(window(), Qt::ActiveWindowFocusReason);
}

WId HeadlessWindow::winId() const
{
    return m_winId;
}

QSurfaceFormat HeadlessWindow::format() const
{
    // Any format can be honoured: the pixels live in client memory.
    return window()->requestedFormat();
}

HeadlessWindow::RenderBuffer HeadlessWindow::renderBuffer()
{
    const QSize size = geometry().size();
    if (size != m_renderSize) {
#ifdef SHADOWLAB_HAVE_OSMESA
        OsMesaOpenGLContext::releaseIfDrawingTo(m_renderPixels.data());
#endif
        m_renderPixels.assign(std::size_t(size.width()) * std::size_t(size.height()), 0u);
        m_renderSize = size;
    }
    return { m_renderPixels.data(), m_renderSize };
}

const void *HeadlessWindow::renderPixels() const
{
    return m_renderPixels.data();
}

void HeadlessWindow::presentRenderBuffer()
{
    if (m_renderPixels.empty())
        return;
    // A view, not a copy, of the render buffer: mirrored() makes the deep copy, and
    // the flip turns OSMesa's bottom-up rows into the top-down rows QImage expects.
    const QImage::Format format =
            window()->format().hasAlpha() ? QImage::Format_RGBA8888_Premultiplied : QImage::Format_RGBX8888;
    const QImage frame(reinterpret_cast<const uchar *>(m_renderPixels.data()), m_renderSize.width(),
                       m_renderSize.height(), m_renderSize.width() * 4, format);
    m_presented = frame.mirrored(false, true).convertToFormat(QImage::Format_ARGB32_Premultiplied);
}

void HeadlessWindow::presentFrame(const QImage &frame)
{
    m_presented = frame.convertToFormat(QImage::Format_ARGB32_Premultiplied);
}

void HeadlessWindow::presentImage(const QImage &source, const QRegion &region, const QPoint &offset)
{
    const QSize size = geometry().size();
    if (m_presented.size() != size) {
        m_presented = QImage(size, QImage::Format_ARGB32_Premultiplied);
        m_presented.fill(Qt::transparent);
    }
    QPainter painter(&m_presented);
    painter.setCompositionMode(QPainter::CompositionMode_Source);
    for (const QRect &rect : region)
        painter.drawImage(rect, source, rect.translated(offset));
}

QImage HeadlessWindow::presentedImage() const
{
    return m_presented;
}

void HeadlessWindow::reportExposure()
{
    QWindowSystemInterface::handleExposeEvent(window(), QRect(QPoint(), geometry().size()));
}

} // namespace shadowlab
