#pragma once
// The fixed-function state of a draw, declared in one description and set whole by
// applyPipeline (Filament's PipelineState, sokol's sg_apply_pipeline): no pass relies on what the
// one before it left, so no pass ends by putting state back. A value-initialised description is
// the default state: no blending, no depth or stencil test, no culling, no clip planes.
//
// Does not: bind programs, buffers, textures or framebuffers, or cache what is set (every call
// sets every field, a few dozen GL calls per draw).
#include <array>

#include <epoxy/gl.h>

namespace nimbus::gpu {

inline constexpr int kMaxDrawBuffers = 8;

struct BlendState {
    bool enabled = false;
    GLenum equationRgb = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
    GLenum srcRgb = GL_ONE, dstRgb = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;
};

struct DepthState {
    bool test = false;
    GLenum compare = GL_GREATER;  // reversed Z
    bool write = true;            // also what a depth clear writes through
};

struct StencilState {
    bool test = false;
    GLenum compare = GL_ALWAYS;
    GLint reference = 0;
    GLuint readMask = 0xFF;
    GLuint writeMask = 0xFF;  // also what a stencil clear writes through
    GLenum fail = GL_KEEP, depthFail = GL_KEEP, pass = GL_KEEP;
};

struct PipelineState {
    std::array<BlendState, kMaxDrawBuffers> blend{};  // per draw buffer
    DepthState depth;
    StencilState stencil;
    bool cullBackFaces = false;  // a draw that culls per material (drawInstances) still may
    bool polygonOffset = false;
    float offsetFactor = 0.0f, offsetUnits = 0.0f;
    int clipDistances = 0;  // gl_ClipDistance[0..n) enabled

    // The same blending on every draw buffer.
    static constexpr PipelineState blending(const BlendState& blend) {
        PipelineState s;
        s.blend.fill(blend);
        return s;
    }
};

// Premultiplied "over" onto a target whose alpha is transmittance: rgb = src + (1 − a)·dst,
// a = (1 − a_src)·a_dst.
inline constexpr BlendState kPremultipliedOver{.enabled = true,
                                               .srcRgb = GL_ONE,
                                               .dstRgb = GL_ONE_MINUS_SRC_ALPHA,
                                               .srcAlpha = GL_ZERO,
                                               .dstAlpha = GL_ONE_MINUS_SRC_ALPHA};
inline constexpr BlendState kAdditive{.enabled = true, .srcRgb = GL_ONE, .dstRgb = GL_ONE, .srcAlpha = GL_ONE, .dstAlpha = GL_ONE};

void applyPipeline(const PipelineState& state);

}  // namespace nimbus::gpu
