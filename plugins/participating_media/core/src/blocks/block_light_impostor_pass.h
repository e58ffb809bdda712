#pragma once
// The `block_light_impostors` pass: each light view's block impostors (shaders/media/block_impostors.*),
// depths and depth moments, one atlas per view, for `block_light_slices` to spread over the slices.
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "blocks/block_impostor_renderer.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// Per light view: its impostor depths and moments. One atlas each, so none is rewritten while
// queued draws read it.
struct BlockLightImpostors {
    std::vector<gpu::ResourceHandle> depths, moments;
};

// Light view i's plan is tile set i + 1 of `blocks`.
BlockLightImpostors addBlockLightImpostorPass(gpu::FrameGraph& graph, const std::vector<BlockViewPlan>& plans,
                                              const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                                              const BlockImpostorRenderer& impostors);

}  // namespace nimbus::media
