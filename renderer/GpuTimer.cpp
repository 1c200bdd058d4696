#include "GpuTimer.h"

namespace shadowlab {

GpuTimer::GpuTimer(GlFunctions* gl) : m_gl(gl), m_queries{makeQuery(gl), makeQuery(gl)} {}

void GpuTimer::begin()
{
    if (!m_enabled)
        return;
    const int next = m_last < 0 ? 0 : 1 - m_last;
    if (m_pending[std::size_t(next)]) {
        // Never reuse a query whose result was not read: drop it so GL does not complain.
        GLuint64 discard = 0;
        m_gl->glGetQueryObjectui64v(m_queries[std::size_t(next)].id(), GL_QUERY_RESULT, &discard);
        m_pending[std::size_t(next)] = false;
    }
    m_gl->glBeginQuery(GL_TIME_ELAPSED, m_queries[std::size_t(next)].id());
    if (!m_labelled[std::size_t(next)]) {    // a query exists only once begun
        labelGlObject(GlLabelKind::Query, m_queries[std::size_t(next)].id(), QStringLiteral("pass timer %1").arg(next));
        m_labelled[std::size_t(next)] = true;
    }
    m_last = next;
}

void GpuTimer::end()
{
    if (!m_enabled)
        return;
    m_gl->glEndQuery(GL_TIME_ELAPSED);
    m_pending[std::size_t(m_last)] = true;
}

std::optional<double> GpuTimer::result(bool wait)
{
    if (!m_enabled || m_last < 0)
        return std::nullopt;
    for (int i : {m_last, 1 - m_last}) {
        if (!m_pending[std::size_t(i)])
            continue;
        const GLuint id = m_queries[std::size_t(i)].id();
        if (!wait) {
            GLint available = 0;
            m_gl->glGetQueryObjectiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available)
                continue;
        }
        GLuint64 nanoseconds = 0;
        m_gl->glGetQueryObjectui64v(id, GL_QUERY_RESULT, &nanoseconds);
        m_pending[std::size_t(i)] = false;
        return double(nanoseconds) * 1e-6;
    }
    return std::nullopt;
}

} // namespace shadowlab
