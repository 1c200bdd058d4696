#pragma once

#include "GlObject.h"

#include <cstdint>
#include <initializer_list>
#include <vector>

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

    bool running() const { return m_running; }

private:
    GlFunctions* m_gl;
    GLenum m_target;
    GlQuery m_query;
    bool m_running = false;
    bool m_ended = false;
};

// Begins `queries` when `on`, and ends whichever still run when it goes: a query left running,
// as an exception out of a pass would leave it, refuses every later one of its target.
class CountingScope {
public:
    CountingScope(bool on, std::initializer_list<CountQuery*> queries) : m_queries(queries)
    {
        if (!on)
            m_queries.clear();
        for (CountQuery* q : m_queries)
            q->begin();
    }
    ~CountingScope() { end(); }
    CountingScope(const CountingScope&) = delete;
    CountingScope& operator=(const CountingScope&) = delete;
    void end()
    {
        for (CountQuery* q : m_queries) {
            if (q->running())
                q->end();
        }
    }

private:
    std::vector<CountQuery*> m_queries;
};

} // namespace shadowlab
