#include "HeadlessIntegrationPlugin.h"

#include "EglDisplay.h"
#include "HeadlessIntegration.h"

namespace shadowlab {

namespace {

#ifdef SHADOWLAB_HAVE_OSMESA
constexpr bool haveOsMesa = true;
#else
constexpr bool haveOsMesa = false;
#endif

} // namespace

QPlatformIntegration *HeadlessIntegrationPlugin::create(const QString &key, const QStringList &params)
{
    Q_UNUSED(params);
    QString backend = key.toLower();
    if (backend == u"headless") {
        // SHADOWLAB_HEADLESS=egl|osmesa forces a backend; otherwise EGL first.
        backend = qEnvironmentVariable("SHADOWLAB_HEADLESS").toLower();
        if (!backend.isEmpty() && backend != u"egl" && backend != u"osmesa") {
            qWarning("SHADOWLAB_HEADLESS='%s' is not a backend; use egl or osmesa", qPrintable(backend));
            return nullptr;
        }
    }
    if (backend == u"egl" || backend.isEmpty()) {
        QString whyNot;
        if (auto egl = EglDisplay::open(&whyNot))
            return new HeadlessIntegration(std::move(egl));
        if (!backend.isEmpty() || !haveOsMesa) {
            qWarning("headless platform: EGL cannot give an OpenGL 3.3 core context (%s)", qPrintable(whyNot));
            return nullptr;
        }
    }
    if (!haveOsMesa) {
        qWarning("headless platform: this build has no OSMesa (its development files were missing); use egl");
        return nullptr;
    }
    return new HeadlessIntegration(nullptr);
}

} // namespace shadowlab
