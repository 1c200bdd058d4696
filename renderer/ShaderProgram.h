#pragma once

#include "GlObject.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <QOpenGLShaderProgram>
#include <QStringList>

#include <memory>

namespace shadowlab {

// Reads a shader from the :/shaders resource, expanding `#include "file"` lines and
// `#include NAME` lines whose file an entry `NAME "file"` of `defines` names or that name a
// uniform block (UniformBlocks.h: its declaration, guarded to appear once), and puts
// `#version 330 core`, the constants shared with C++ (core/ShaderConstants.h) and one `#define`
// per other entry in front ("NAME" or "NAME VALUE").
// Throws RenderError naming the file when it or an include is missing.
QByteArray loadShaderSource(const QString& file, const QStringList& defines);

// A linked program built from a vertex and a fragment file with injected defines, each uniform
// block it declares read from the block's binding. Compile and link failures throw RenderError
// with the file names and the driver's log.
class ShaderProgram {
public:
    ShaderProgram(GlFunctions* gl, const QString& vertexFile, const QString& fragmentFile, const QStringList& defines);

    void bind() { m_program->bind(); }
    GLint uniform(const char* name) const;
    GLuint id() const { return m_program->programId(); }

    void set(GLint location, float value);
    void set(GLint location, int value);
    void set(GLint location, const glm::vec2& value);
    void set(GLint location, const glm::vec3& value);
    void set(GLint location, const glm::mat3& value);
    void set(GLint location, const glm::mat4& value);

private:
    // Reads the uniform block `name` from uniform buffer binding `binding`, where the program
    // has it active (a variant may not read it).
    void bindUniformBlock(const char* name, GLuint binding);

    GlFunctions* m_gl;
    std::unique_ptr<QOpenGLShaderProgram> m_program;
};

} // namespace shadowlab
