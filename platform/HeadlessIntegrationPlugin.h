#pragma once

#include <qpa/qplatformintegrationplugin.h>

namespace shadowlab {

// Entry point Qt's platform factory asks for the keys "headless" (EGL if it can give a
// 3.3 core context, else OSMesa; SHADOWLAB_HEADLESS=egl|osmesa forces one), "egl" and
// "osmesa". Built as a static plugin; HeadlessPlatform.cpp imports it so linking the
// library is enough.
class HeadlessIntegrationPlugin : public QPlatformIntegrationPlugin
{
    Q_OBJECT
    Q_PLUGIN_METADATA(IID QPlatformIntegrationFactoryInterface_iid FILE "headless.json")

public:
    QPlatformIntegration *create(const QString &key, const QStringList &params) override;
};

} // namespace shadowlab
