#pragma once

#include <QString>

namespace shadowlab {

// What the import worker may spend on one model file before its parent stops it (IsolatedImport.h).
// Process-wide: the command line's --import-time-limit and --import-memory-limit set them, and in
// the explorer File > Import Limits and a refusal's Try Again, for the rest of the run.
struct ImportLimits {
    double timeSeconds = 30.0;      // wall time, 1..3600; CPU time is capped a little above it
    int memoryMiB = 4096;           // the worker's address space, 256..65536
    int outputMiB = 2048;           // what it may send back, 1..8192 (10^7 triangles take ~450 MiB)

    // Throws SettingsError naming the option and its range.
    void validate() const;
};

ImportLimits importLimits();
// Throws like ImportLimits::validate() and then keeps the old limits.
void setImportLimits(const ImportLimits& limits);

} // namespace shadowlab
