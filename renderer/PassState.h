#pragma once

#include "GlObject.h"

#include <QRect>

namespace shadowlab {

// The fixed-function state one pass (or one draw of a pass) relies on, as a value: applied
// whole at its start, so no pass depends on what the previous one, a QPainter or a caller's
// own drawing left behind. Defaults are GL's own.
struct PassState {
    QRect viewport;                     // empty: leave the viewport as it is
    bool depthTest = false;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = true;
    bool depthClamp = false;            // clamp instead of clipping at near/far
    double depthRangeNear = 0.0;        // glDepthRange: where near and far land in the depth buffer
    double depthRangeFar = 1.0;
    GLenum cullFace = GL_NONE;          // GL_NONE (no culling), GL_BACK or GL_FRONT
    float polygonOffsetFactor = 0.0f;   // both 0: no polygon offset
    float polygonOffsetUnits = 0.0f;
    bool blend = false;
    GLenum blendSourceRgb = GL_ONE;     // glBlendFuncSeparate
    GLenum blendDestinationRgb = GL_ZERO;
    GLenum blendSourceAlpha = GL_ONE;
    GLenum blendDestinationAlpha = GL_ZERO;
    float blendConstantAlpha = 0.0f;    // for GL_CONSTANT_ALPHA
    bool zeroToOneDepth = false;        // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); needs clip control
};

// Whether the current context has glClipControl (GL 4.5 or ARB_clip_control).
bool hasClipControl();

// Sets every field of `state`, plus the state no pass here uses (scissor, stencil, colour
// mask all on). The clip-control mode is set only where the context has it.
void applyPassState(GlFunctions* gl, const PassState& state);

} // namespace shadowlab
