#include "OsMesaIntegrationPlugin.h"

#include "OsMesaIntegration.h"

namespace shadowlab {

QPlatformIntegration *OsMesaIntegrationPlugin::create(const QString &key, const QStringList &params)
{
    Q_UNUSED(params);
    if (key.compare(QLatin1String("osmesa"), Qt::CaseInsensitive) != 0)
        return nullptr;
    return new OsMesaIntegration;
}

} // namespace shadowlab
