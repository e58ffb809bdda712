#include "nimbus/gpu/pipeline_state.h"

namespace nimbus::gpu {
namespace {

void enable(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }

}  // namespace

void applyPipeline(const PipelineState& s) {
    for (GLuint i = 0; i < static_cast<GLuint>(kMaxDrawBuffers); ++i) {
        const BlendState& b = s.blend[i];
        b.enabled ? glEnablei(GL_BLEND, i) : glDisablei(GL_BLEND, i);
        glBlendEquationSeparatei(i, b.equationRgb, b.equationAlpha);
        glBlendFuncSeparatei(i, b.srcRgb, b.dstRgb, b.srcAlpha, b.dstAlpha);
    }
    enable(GL_DEPTH_TEST, s.depth.test);
    glDepthFunc(s.depth.compare);
    glDepthMask(s.depth.write ? GL_TRUE : GL_FALSE);
    enable(GL_STENCIL_TEST, s.stencil.test);
    glStencilFunc(s.stencil.compare, s.stencil.reference, s.stencil.readMask);
    glStencilMask(s.stencil.writeMask);
    glStencilOp(s.stencil.fail, s.stencil.depthFail, s.stencil.pass);
    enable(GL_CULL_FACE, s.cullBackFaces);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    enable(GL_POLYGON_OFFSET_FILL, s.polygonOffset);
    glPolygonOffset(s.offsetFactor, s.offsetUnits);
    for (int plane = 0; plane < 8; ++plane) enable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(plane), plane < s.clipDistances);
}

}  // namespace nimbus::gpu
