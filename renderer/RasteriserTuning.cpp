#include "RasteriserTuning.h"

#include <mutex>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace shadowlab {

bool isSoftwareRenderer(const QString& rendererString)
{
    const QString r = rendererString.toLower();
    return r.contains(QLatin1String("llvmpipe")) || r.contains(QLatin1String("softpipe")) || r.contains(QLatin1String("swrast"))
        || r.contains(QLatin1String("software"));
}

RasteriserTuning RasteriserTuning::of(RasteriserProfile profile, const QString& rendererString)
{
    return of(profile, isSoftwareRenderer(rendererString));
}

RasteriserTuning RasteriserTuning::of(RasteriserProfile profile, bool softwareDriver)
{
    const bool software = profile == RasteriserProfile::Software || (profile == RasteriserProfile::Auto && softwareDriver);
    return {.software = software, .skipsOutOfReach = software, .depthSlices = software, .wideTwoChannelMoments = software,
            .clearsWrittenMoments = software, .cpuVirtualRequests = software, .rangesWrittenTexels = software};
}

QString profileName(const RasteriserTuning& tuning)
{
    return tuning.software ? QStringLiteral("software") : QStringLiteral("hardware");
}

void retainFreedHeapForSoftwareRasteriser(const QString& rendererString)
{
#ifdef __GLIBC__
    static std::once_flag once;
    if (!isSoftwareRenderer(rendererString))
        return;
    std::call_once(once, [] {
        // The threshold first: setting the trim threshold alone freezes glibc's mmap threshold at
        // 128 KiB, so every larger block (a 16 MB read-back, a texture) was mapped fresh and
        // faulted in page by page. Older glibc refuses a threshold above 32 MB.
        constexpr int kLargest = 256 << 20, kOlderLargest = 32 << 20;
        if (mallopt(M_MMAP_THRESHOLD, kLargest) == 1 || mallopt(M_MMAP_THRESHOLD, kOlderLargest) == 1)
            mallopt(M_TRIM_THRESHOLD, kLargest);
    });
#else
    Q_UNUSED(rendererString);
#endif
}

} // namespace shadowlab
