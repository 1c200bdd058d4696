#pragma once

#include "GlObject.h"

#include <cstdint>

namespace shadowlab {

// One GL counting query (GL_PRIMITIVES_GENERATED, GL_SAMPLES_PASSED) over the draws between
// begin() and end(): counts that are the same on any GPU. Reading the result waits for those
// draws; on a software rasteriser a query also makes the next pass wait, so only frames that
// are counted, never timed ones, run them (Renderer::setCounting).
class CountQuery {
public:
    CountQuery(GlFunctions* gl, GLenum target) : m_gl(gl), m_target(target) {}

    void begin();
    void end();
    // The count of the last begin()/end(), waiting for it; -1 when none ran.
    std::int64_t result();

private:
    GlFunctions* m_gl;
    GLenum m_target;
    GlQuery m_query;
    bool m_ended = false;
};

} // namespace shadowlab
