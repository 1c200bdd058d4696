#include "HeadlessTheme.h"

#include <QtCore/QStringList>
#include <QtCore/QVariant>

namespace shadowlab {

QVariant HeadlessTheme::themeHint(ThemeHint hint) const
{
    if (hint == StyleNames)
        return QStringList{ QStringLiteral("Fusion") };
    return QPlatformTheme::themeHint(hint);
}

} // namespace shadowlab
