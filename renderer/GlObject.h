#pragma once

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <utility>

namespace shadowlab {

using GlFunctions = QOpenGLFunctions_3_3_Core;

// Move-only owner of one GL object name, deleted through the functions that created it.
// The context (or one sharing with it, for shareable objects) must be current on destruction.
template <void (GlFunctions::*Delete)(GLsizei, const GLuint*)>
class GlObject {
public:
    GlObject() = default;
    GlObject(GlFunctions* gl, GLuint id) : m_gl(gl), m_id(id) {}
    ~GlObject() { reset(); }

    GlObject(GlObject&& other) noexcept : m_gl(other.m_gl), m_id(std::exchange(other.m_id, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept
    {
        if (this != &other) {
            reset();
            m_gl = other.m_gl;
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }

    void reset()
    {
        if (m_id != 0)
            (m_gl->*Delete)(1, &m_id);
        m_id = 0;
    }

private:
    GlFunctions* m_gl = nullptr;
    GLuint m_id = 0;
};

using GlBuffer = GlObject<&GlFunctions::glDeleteBuffers>;
using GlVertexArray = GlObject<&GlFunctions::glDeleteVertexArrays>;
using GlTexture = GlObject<&GlFunctions::glDeleteTextures>;
using GlFramebuffer = GlObject<&GlFunctions::glDeleteFramebuffers>;
using GlSampler = GlObject<&GlFunctions::glDeleteSamplers>;
using GlQuery = GlObject<&GlFunctions::glDeleteQueries>;

template <typename Object, void (GlFunctions::*Gen)(GLsizei, GLuint*)>
Object makeGlObject(GlFunctions* gl)
{
    GLuint id = 0;
    (gl->*Gen)(1, &id);
    return Object(gl, id);
}

enum class GlLabelKind { Buffer, Framebuffer, Program, Query, Sampler, Texture, VertexArray };

// Names a GL object for debuggers and driver messages (glObjectLabel) where the context has
// KHR_debug or GL 4.3, and does nothing elsewhere. Buffers, textures, vertex arrays,
// framebuffers and queries exist only once bound (or begun): label them after that.
void labelGlObject(GlLabelKind kind, GLuint id, const QString& label);

inline GlBuffer makeBuffer(GlFunctions* gl) { return makeGlObject<GlBuffer, &GlFunctions::glGenBuffers>(gl); }
inline GlVertexArray makeVertexArray(GlFunctions* gl) { return makeGlObject<GlVertexArray, &GlFunctions::glGenVertexArrays>(gl); }
inline GlTexture makeTexture(GlFunctions* gl) { return makeGlObject<GlTexture, &GlFunctions::glGenTextures>(gl); }
inline GlFramebuffer makeFramebuffer(GlFunctions* gl) { return makeGlObject<GlFramebuffer, &GlFunctions::glGenFramebuffers>(gl); }
inline GlSampler makeSampler(GlFunctions* gl) { return makeGlObject<GlSampler, &GlFunctions::glGenSamplers>(gl); }
inline GlQuery makeQuery(GlFunctions* gl) { return makeGlObject<GlQuery, &GlFunctions::glGenQueries>(gl); }

} // namespace shadowlab
