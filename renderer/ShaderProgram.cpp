#include "ShaderProgram.h"

#include "RenderError.h"
#include "ShaderConstants.h"
#include "UniformBlocks.h"

#include <glm/gtc/type_ptr.hpp>

#include <QFile>
#include <QRegularExpression>

namespace shadowlab {

namespace {

QByteArray readResource(const QString& file, const QString& includedFrom)
{
    QFile f(QStringLiteral(":/shaders/") + file);
    if (!f.open(QIODevice::ReadOnly)) {
        throw RenderError(includedFrom.isEmpty()
                              ? QStringLiteral("shader file '%1' is missing from the resources").arg(file)
                              : QStringLiteral("shader file '%1' (included from '%2') is missing").arg(file, includedFrom));
    }
    return f.readAll();
}

// The file a `#include NAME` line names through a define `NAME "file"` (the variant picks it).
QString includedByDefine(const QString& name, const QStringList& defines, const QString& file)
{
    static const QRegularExpression define(QStringLiteral(R"re(^(\w+)\s+"([^"]+)"$)re"));
    for (const QString& d : defines) {
        const QRegularExpressionMatch m = define.match(d);
        if (m.hasMatch() && m.captured(1) == name)
            return m.captured(2);
    }
    throw RenderError(QStringLiteral("'%1' includes %2, which the variant does not define as a file").arg(file, name));
}

// `#include NAME` of a uniform block (UniformBlocks.h) gives its declaration behind an include
// guard: several files that read a block each say so, some inside an #ifdef.
QByteArray expandIncludes(const QString& file, const QString& includedFrom, const QStringList& defines, int depth)
{
    if (depth > 8)
        throw RenderError(QStringLiteral("shader includes nest too deep at '%1' (a cycle?)").arg(file));
    static const QRegularExpression include(QStringLiteral(R"re(^\s*#include\s+(?:"([^"]+)"|(\w+))\s*(?://.*)?$)re"));
    QByteArray out;
    const QList<QByteArray> lines = readResource(file, includedFrom).split('\n');
    for (const QByteArray& line : lines) {
        const QRegularExpressionMatch m = include.match(QString::fromUtf8(line));
        if (const UniformBlockDeclaration* block = m.hasMatch() ? uniformBlock(m.captured(2)) : nullptr) {
            const QByteArray guard = QByteArray("SHADOWLAB_BLOCK_") + block->name;
            out += "#ifndef " + guard + "\n#define " + guard + '\n' + block->glsl + "#endif\n";
        } else if (m.hasMatch()) {
            const QString included = m.captured(1).isEmpty() ? includedByDefine(m.captured(2), defines, file) : m.captured(1);
            out += expandIncludes(included, file, defines, depth + 1);
        } else {
            out += line + '\n';
        }
    }
    return out;
}

} // namespace

QByteArray loadShaderSource(const QString& file, const QStringList& defines)
{
    QByteArray source = "#version 330 core\n" + glslConstants();
    for (const QString& define : defines) {
        if (!define.endsWith(QLatin1Char('"')))    // file names are for #include, not for GLSL
            source += "#define " + define.toUtf8() + '\n';
    }
    return source + expandIncludes(file, QString(), defines, 0);
}

ShaderProgram::ShaderProgram(GlFunctions* gl, const QString& vertexFile, const QString& fragmentFile, const QStringList& defines)
    : m_gl(gl), m_program(std::make_unique<QOpenGLShaderProgram>())
{
    const QString variant = defines.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(defines.join(QStringLiteral(", ")));
    if (!m_program->addShaderFromSourceCode(QOpenGLShader::Vertex, loadShaderSource(vertexFile, defines)))
        throw RenderError(QStringLiteral("%1%2 does not compile:\n%3").arg(vertexFile, variant, m_program->log()));
    if (!m_program->addShaderFromSourceCode(QOpenGLShader::Fragment, loadShaderSource(fragmentFile, defines)))
        throw RenderError(QStringLiteral("%1%2 does not compile:\n%3").arg(fragmentFile, variant, m_program->log()));
    if (!m_program->link())
        throw RenderError(QStringLiteral("%1 + %2%3 do not link:\n%4").arg(vertexFile, fragmentFile, variant, m_program->log()));
    labelGlObject(GlLabelKind::Program, m_program->programId(), vertexFile + QStringLiteral(" + ") + fragmentFile + variant);
    // Each block the program reads, at the binding its buffer is uploaded to (UniformBuffer).
    for (const UniformBlockDeclaration& block : uniformBlocks())
        bindUniformBlock(block.name, block.binding);
}

GLint ShaderProgram::uniform(const char* name) const
{
    return m_program->uniformLocation(name);
}

void ShaderProgram::bindUniformBlock(const char* name, GLuint binding)
{
    if (const GLuint index = m_gl->glGetUniformBlockIndex(id(), name); index != GL_INVALID_INDEX)
        m_gl->glUniformBlockBinding(id(), index, binding);
}

void ShaderProgram::set(GLint location, float value) { m_gl->glUniform1f(location, value); }
void ShaderProgram::set(GLint location, int value) { m_gl->glUniform1i(location, value); }
void ShaderProgram::set(GLint location, const glm::vec2& value) { m_gl->glUniform2fv(location, 1, glm::value_ptr(value)); }
void ShaderProgram::set(GLint location, const glm::vec3& value) { m_gl->glUniform3fv(location, 1, glm::value_ptr(value)); }
void ShaderProgram::set(GLint location, const glm::mat3& value) { m_gl->glUniformMatrix3fv(location, 1, GL_FALSE, glm::value_ptr(value)); }
void ShaderProgram::set(GLint location, const glm::mat4& value) { m_gl->glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(value)); }

} // namespace shadowlab
