#include "ImportLimits.h"

#include "SettingsError.h"

#include <cmath>
#include <mutex>

namespace shadowlab {

namespace {

std::mutex g_limitsMutex;
ImportLimits g_limits;

} // namespace

void ImportLimits::validate() const
{
    if (!std::isfinite(timeSeconds) || timeSeconds < 1.0 || timeSeconds > 3600.0)
        throw SettingsError(QStringLiteral("--import-time-limit"),
                            QStringLiteral("%1 s is outside 1 .. 3600 s, how long one model file may take to read; give one inside, e.g. "
                                           "--import-time-limit 60")
                                .arg(timeSeconds));
    if (memoryMiB < 256 || memoryMiB > 65536)
        throw SettingsError(QStringLiteral("--import-memory-limit"),
                            QStringLiteral("%1 MiB is outside 256 .. 65536 MiB, the memory the importer may use for one file; give one "
                                           "inside, e.g. --import-memory-limit 8192")
                                .arg(memoryMiB));
    if (outputMiB < 1 || outputMiB > 8192)
        throw SettingsError(QStringLiteral("import-output-limit"), QStringLiteral("%1 MiB is outside 1 .. 8192 MiB").arg(outputMiB));
}

ImportLimits importLimits()
{
    std::lock_guard lock(g_limitsMutex);
    return g_limits;
}

void setImportLimits(const ImportLimits& limits)
{
    limits.validate();
    std::lock_guard lock(g_limitsMutex);
    g_limits = limits;
}

} // namespace shadowlab
