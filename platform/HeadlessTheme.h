#pragma once

#include <qpa/qplatformtheme.h>

namespace shadowlab {

// Pins the widget style so headless screenshots look the same on every machine,
// whatever desktop settings the environment happens to carry.
class HeadlessTheme : public QPlatformTheme
{
public:
    QVariant themeHint(ThemeHint hint) const override;
};

} // namespace shadowlab
