#pragma once

#include <qpa/qplatformoffscreensurface.h>

#include <QtCore/QSize>

#include <cstdint>
#include <vector>

namespace shadowlab {

// OSMesa cannot make a context current without a colour buffer, so each offscreen
// surface carries a small private one (EGL contexts are current with no surface and
// ignore it). Real rendering goes into FBOs.
class HeadlessOffscreenSurface : public QPlatformOffscreenSurface
{
public:
    explicit HeadlessOffscreenSurface(QOffscreenSurface *surface);
    ~HeadlessOffscreenSurface() override;

    bool isValid() const override;

    void *pixels();
    QSize size() const;

private:
    std::vector<std::uint32_t> m_pixels;
};

} // namespace shadowlab
