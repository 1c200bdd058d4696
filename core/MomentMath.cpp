#include "MomentMath.h"

#include "ShadowTechnique.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

bool isMomentTechnique(FilterMode mode)
{
    return shadowTechnique(mode).map == ShadowMapKind::Moments;
}

double maxExponent(FilterMode mode, MomentFormat format)
{
    const double largest = format == MomentFormat::Rgba16F ? 65504.0 : double(std::numeric_limits<float>::max());
    // A hair below the limit: the blur's weights may round their sum above 1.
    const double logLargest = std::log(largest) - 0.01;
    switch (mode) {
    case FilterMode::Evsm2:
    case FilterMode::Evsm4:
        return 0.5 * logLargest;
    case FilterMode::Esm:
        return logLargest;
    default:
        return 0.0;
    }
}

MomentWarp momentWarp(const Settings& settings)
{
    const double limit = maxExponent(settings.filter.mode, settings.moments.format);
    MomentWarp w;
    w.positive = std::min(settings.filter.positiveExponent, limit);
    w.negative = settings.filter.mode == FilterMode::Evsm4 ? std::min(settings.filter.negativeExponent, limit) : 0.0;
    return w;
}

bool blursInLookup(const Settings& settings)
{
    const MomentSettings& m = settings.moments;
    if (m.blur <= 1 || m.mipmaps || m.anisotropy > 1 || m.blurAt == MomentBlurAt::Map)
        return false;
    return m.blurAt == MomentBlurAt::Lookup || m.blur <= kWidestLookupBlur;
}

int mapBlurWidth(const Settings& settings)
{
    return blursInLookup(settings) ? 0 : settings.moments.blur;
}

int lookupBlurRadius(const Settings& settings)
{
    return blursInLookup(settings) ? (settings.moments.blur - 1) / 2 : 0;
}

} // namespace shadowlab
