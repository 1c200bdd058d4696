#pragma once

#include <qpa/qplatformintegration.h>

#include <memory>

class QPlatformFontDatabase;
class QPlatformServices;

namespace shadowlab {

class EglDisplay;
class HeadlessScreen;

// The headless platform: one fixed screen, windows backed by client memory, and
// OpenGL from EGL with no surface or from OSMesa. Everything a QOpenGLWidget in a
// QMainWindow needs, nothing that talks to a display server.
class HeadlessIntegration : public QPlatformIntegration
{
public:
    // With an EGL display, contexts come from EGL; without one, from OSMesa.
    explicit HeadlessIntegration(std::unique_ptr<EglDisplay> egl);
    ~HeadlessIntegration() override;

    bool hasCapability(Capability cap) const override;

    QPlatformWindow *createPlatformWindow(QWindow *window) const override;
    QPlatformBackingStore *createPlatformBackingStore(QWindow *window) const override;
    QPlatformOpenGLContext *createPlatformOpenGLContext(QOpenGLContext *context) const override;
    QPlatformOffscreenSurface *createPlatformOffscreenSurface(QOffscreenSurface *surface) const override;
    QAbstractEventDispatcher *createEventDispatcher() const override;

    QPlatformFontDatabase *fontDatabase() const override;
    QPlatformServices *services() const override;
    QStringList themeNames() const override;
    QPlatformTheme *createPlatformTheme(const QString &name) const override;

private:
    std::unique_ptr<EglDisplay> m_egl;
    std::unique_ptr<QPlatformFontDatabase> m_fontDatabase;
    std::unique_ptr<QPlatformServices> m_services;
    HeadlessScreen *m_screen = nullptr; // owned by QtGui once announced
};

} // namespace shadowlab
