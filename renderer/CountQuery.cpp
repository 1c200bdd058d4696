#include "CountQuery.h"

namespace shadowlab {

void CountQuery::begin()
{
    if (!m_query)
        m_query = makeGlObject<GlQuery, &GlFunctions::glGenQueries>(m_gl);
    m_gl->glBeginQuery(m_target, m_query.id());
    m_running = true;
    m_ended = false;
}

void CountQuery::end()
{
    m_gl->glEndQuery(m_target);
    m_running = false;
    m_ended = true;
}

std::int64_t CountQuery::result()
{
    if (!m_ended)
        return -1;
    m_ended = false;
    GLuint64 count = 0;
    m_gl->glGetQueryObjectui64v(m_query.id(), GL_QUERY_RESULT, &count);
    return std::int64_t(count);
}

} // namespace shadowlab
