#pragma once

#include <QtCore/QString>

#include <EGL/egl.h>

#include <memory>

namespace shadowlab {

// An initialised EGL display that needs no window system: Mesa's surfaceless platform
// (any Mesa driver, llvmpipe included), else an EGL device (a GPU with no display, as with
// NVIDIA's driver). Contexts made on it are current with no surface, so windows draw into
// framebuffer objects (see EglOpenGLContext).
class EglDisplay
{
public:
    // The first display that can create an OpenGL 3.3 core context with no config and no
    // surface; null with the reasons in `whyNot` when there is none.
    static std::unique_ptr<EglDisplay> open(QString *whyNot);
    ~EglDisplay();

    EglDisplay(const EglDisplay &) = delete;
    EglDisplay &operator=(const EglDisplay &) = delete;

    EGLDisplay handle() const { return m_display; }
    // "surfaceless" or "device": which EGL platform the display came from.
    QString platform() const { return m_platform; }

private:
    EglDisplay(EGLDisplay display, QString platform) : m_display(display), m_platform(std::move(platform)) {}

    EGLDisplay m_display;
    QString m_platform;
};

} // namespace shadowlab
