#include "HeadlessOffscreenSurface.h"

#ifdef SHADOWLAB_HAVE_OSMESA
#include "OsMesaOpenGLContext.h"
#endif

namespace shadowlab {

namespace {
// One llvmpipe tile; big enough that code peeking at the default viewport sees
// something sane, small enough to be free.
constexpr QSize bufferSize(64, 64);
} // namespace

HeadlessOffscreenSurface::HeadlessOffscreenSurface(QOffscreenSurface *surface)
    : QPlatformOffscreenSurface(surface)
    , m_pixels(std::size_t(bufferSize.width()) * std::size_t(bufferSize.height()), 0u)
{
}

HeadlessOffscreenSurface::~HeadlessOffscreenSurface()
{
#ifdef SHADOWLAB_HAVE_OSMESA
    // See HeadlessWindow: a bound buffer must outlive the binding.
    OsMesaOpenGLContext::releaseIfDrawingTo(m_pixels.data());
#endif
}

bool HeadlessOffscreenSurface::isValid() const
{
    return true;
}

void *HeadlessOffscreenSurface::pixels()
{
    return m_pixels.data();
}

QSize HeadlessOffscreenSurface::size() const
{
    return bufferSize;
}

} // namespace shadowlab
