#include "OsMesaOffscreenSurface.h"

#include "OsMesaOpenGLContext.h"

namespace shadowlab {

namespace {
// One llvmpipe tile; big enough that code peeking at the default viewport sees
// something sane, small enough to be free.
constexpr QSize bufferSize(64, 64);
} // namespace

OsMesaOffscreenSurface::OsMesaOffscreenSurface(QOffscreenSurface *surface)
    : QPlatformOffscreenSurface(surface)
    , m_pixels(std::size_t(bufferSize.width()) * std::size_t(bufferSize.height()), 0u)
{
}

OsMesaOffscreenSurface::~OsMesaOffscreenSurface()
{
    // See OsMesaWindow: a bound buffer must outlive the binding.
    OsMesaOpenGLContext::releaseIfDrawingTo(m_pixels.data());
}

bool OsMesaOffscreenSurface::isValid() const
{
    return true;
}

void *OsMesaOffscreenSurface::pixels()
{
    return m_pixels.data();
}

QSize OsMesaOffscreenSurface::size() const
{
    return bufferSize;
}

} // namespace shadowlab
