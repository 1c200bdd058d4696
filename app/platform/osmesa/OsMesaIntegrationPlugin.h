#pragma once

#include <qpa/qplatformintegrationplugin.h>

namespace shadowlab {

// Entry point Qt's platform factory asks for the "osmesa" key. Built as a static
// plugin; HeadlessPlatform.cpp imports it so linking the library is enough.
class OsMesaIntegrationPlugin : public QPlatformIntegrationPlugin
{
    Q_OBJECT
    Q_PLUGIN_METADATA(IID QPlatformIntegrationFactoryInterface_iid FILE "osmesa.json")

public:
    QPlatformIntegration *create(const QString &key, const QStringList &params) override;
};

} // namespace shadowlab
