#include "GlObject.h"

#include <QOpenGLContext>

// KHR_debug / GL 4.3 names; the 3.3 headers may not have them.
#ifndef GL_BUFFER
#define GL_BUFFER 0x82E0
#endif
#ifndef GL_PROGRAM
#define GL_PROGRAM 0x82E2
#endif
#ifndef GL_QUERY
#define GL_QUERY 0x82E3
#endif
#ifndef GL_SAMPLER
#define GL_SAMPLER 0x82E6
#endif
#ifndef GL_VERTEX_ARRAY
#define GL_VERTEX_ARRAY 0x8074
#endif

namespace shadowlab {

namespace {

using ObjectLabel = void(QOPENGLF_APIENTRYP)(GLenum identifier, GLuint name, GLsizei length, const GLchar* label);

ObjectLabel objectLabelFunction()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (!context)
        return nullptr;
    const bool core43 = context->format().version() >= qMakePair(4, 3);
    if (!core43 && !context->hasExtension(QByteArrayLiteral("GL_KHR_debug")))
        return nullptr;
    return reinterpret_cast<ObjectLabel>(context->getProcAddress("glObjectLabel"));
}

} // namespace

void labelGlObject(GlLabelKind kind, GLuint id, const QString& label)
{
    const ObjectLabel objectLabel = objectLabelFunction();
    if (!objectLabel || id == 0)
        return;
    GLenum identifier = GL_TEXTURE;
    switch (kind) {
    case GlLabelKind::Buffer: identifier = GL_BUFFER; break;
    case GlLabelKind::Framebuffer: identifier = GL_FRAMEBUFFER; break;
    case GlLabelKind::Program: identifier = GL_PROGRAM; break;
    case GlLabelKind::Query: identifier = GL_QUERY; break;
    case GlLabelKind::Sampler: identifier = GL_SAMPLER; break;
    case GlLabelKind::Texture: identifier = GL_TEXTURE; break;
    case GlLabelKind::VertexArray: identifier = GL_VERTEX_ARRAY; break;
    }
    const QByteArray text = label.toUtf8();
    objectLabel(identifier, id, GLsizei(text.size()), text.constData());
}

} // namespace shadowlab
