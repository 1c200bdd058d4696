#pragma once

#include "GlObject.h"

#include <array>
#include <optional>

namespace shadowlab {

// GL_TIME_ELAPSED around one pass. Two queries in flight, so an interactive view can read
// the previous frame's time without stalling; a benchmark waits for the current one.
// Switched off, it issues no query and has no result: a software rasteriser's timer misses its
// deferred rasterisation, and each query there costs the next pass a wait per tile.
class GpuTimer {
public:
    explicit GpuTimer(GlFunctions* gl);

    // Between passes only, never between begin() and end().
    void setEnabled(bool enabled) { m_enabled = enabled; }

    void begin();
    void end();
    // Milliseconds of the pass just ended (wait = true, blocks until the GPU is done) or of the
    // newest finished one (wait = false; nullopt when none is ready yet).
    std::optional<double> result(bool wait);

private:
    GlFunctions* m_gl;
    std::array<GlQuery, 2> m_queries;
    std::array<bool, 2> m_pending{false, false};
    std::array<bool, 2> m_labelled{false, false};
    int m_last = -1;
    bool m_enabled = true;
};

} // namespace shadowlab
