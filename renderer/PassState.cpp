#include "PassState.h"

#include <QOpenGLContext>

// Core in GL 4.5; the 3.3 headers may not name them.
#ifndef GL_NEGATIVE_ONE_TO_ONE
#define GL_NEGATIVE_ONE_TO_ONE 0x935E
#endif
#ifndef GL_ZERO_TO_ONE
#define GL_ZERO_TO_ONE 0x935F
#endif

namespace shadowlab {

namespace {

using ClipControl = void(QOPENGLF_APIENTRYP)(GLenum, GLenum);

ClipControl clipControlFunction()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (!context)
        return nullptr;
    const bool core45 = context->format().version() >= qMakePair(4, 5);
    if (!core45 && !context->hasExtension(QByteArrayLiteral("GL_ARB_clip_control")))
        return nullptr;
    return reinterpret_cast<ClipControl>(context->getProcAddress("glClipControl"));
}

void enable(GlFunctions* gl, GLenum capability, bool on)
{
    if (on)
        gl->glEnable(capability);
    else
        gl->glDisable(capability);
}

} // namespace

bool hasClipControl()
{
    return clipControlFunction() != nullptr;
}

void applyPassState(GlFunctions* gl, const PassState& state)
{
    if (!state.viewport.isEmpty())
        gl->glViewport(state.viewport.x(), state.viewport.y(), state.viewport.width(), state.viewport.height());
    enable(gl, GL_DEPTH_TEST, state.depthTest);
    gl->glDepthFunc(state.depthFunc);
    gl->glDepthMask(state.depthWrite ? GL_TRUE : GL_FALSE);
    enable(gl, GL_DEPTH_CLAMP, state.depthClamp);
    gl->glDepthRange(state.depthRangeNear, state.depthRangeFar);
    enable(gl, GL_CULL_FACE, state.cullFace != GL_NONE);
    if (state.cullFace != GL_NONE)
        gl->glCullFace(state.cullFace);
    const bool offset = state.polygonOffsetFactor != 0.0f || state.polygonOffsetUnits != 0.0f;
    enable(gl, GL_POLYGON_OFFSET_FILL, offset);
    gl->glPolygonOffset(state.polygonOffsetFactor, state.polygonOffsetUnits);
    enable(gl, GL_BLEND, state.blend);
    gl->glBlendFuncSeparate(state.blendSourceRgb, state.blendDestinationRgb, state.blendSourceAlpha, state.blendDestinationAlpha);
    gl->glBlendColor(0.0f, 0.0f, 0.0f, state.blendConstantAlpha);
    gl->glDisable(GL_SCISSOR_TEST);
    gl->glDisable(GL_STENCIL_TEST);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Looked up per pass rather than cached: a pass object may outlive the context it was made in.
    if (ClipControl clipControl = clipControlFunction())
        clipControl(GL_LOWER_LEFT, state.zeroToOneDepth ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

} // namespace shadowlab
