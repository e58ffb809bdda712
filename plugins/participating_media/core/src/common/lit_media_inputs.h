#pragma once
// What the mode passes share: the media target they write (cleared to no radiance and full
// transmittance, then blended premultiplied back to front), the scene depth they stop at, and the
// mesh shadow map and light slices they light with.
#include "common/media_target.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

struct LitMediaInputs {
    gpu::ResourceHandle media, depth, shadowMap, slices;
};

// In a pass's setup: the target it draws (a new RGBA32F texture of target.size, or the output
// target.over names).
gpu::ResourceHandle declareMediaTarget(gpu::PassBuilder& builder, const MediaTarget& target);
// In a pass's setup: declares the target (declareMediaTarget) and reads the rest when the frame has them.
void declareLitMediaInputs(gpu::PassBuilder& builder, const GraphFrame& context, const MediaTarget& target, LitMediaInputs& d);
// The reads alone, for a pass that draws into a target it did not create (the edges).
void readLitMediaInputs(gpu::PassBuilder& builder, const GraphFrame& context, LitMediaInputs& d);
// In its execution: binds depth, shadow map and slices at their units (gpu_bindings.h).
void bindLitMediaInputs(const gpu::PassResources& resources, const LitMediaInputs& d);

// Binds a framebuffer on the media target `texture` with the viewport on it, cleared to (0, 0, 0, 1).
gpu::Framebuffer bindClearedMediaTarget(GLuint texture, glm::ivec2 size);
// The same for `target`'s texture, cleared only where it is a layer of its own (not target.over).
gpu::Framebuffer bindMediaTarget(GLuint texture, const MediaTarget& target);
// Premultiplied "over" with alpha as the product of (1 − α): rgb = src + (1 − α)·dst, a = (1 − α)·a;
// no depth test or culling (the shaders clip against the scene depth themselves).
inline constexpr gpu::PipelineState kMediaOver = gpu::PipelineState::blending(gpu::kPremultipliedOver);
// The same over the host's output: rgb = src + (1 − α)·opaque, its alpha (1) kept.
inline constexpr gpu::PipelineState kMediaOverOutput = gpu::PipelineState::blending(
    {.enabled = true, .srcRgb = GL_ONE, .dstRgb = GL_ONE_MINUS_SRC_ALPHA, .srcAlpha = GL_ZERO, .dstAlpha = GL_ONE});
// kMediaOver into a layer of the target's own, kMediaOverOutput over the output.
inline const gpu::PipelineState& mediaOver(const MediaTarget& target) { return target.over.valid() ? kMediaOverOutput : kMediaOver; }

}  // namespace nimbus::media
