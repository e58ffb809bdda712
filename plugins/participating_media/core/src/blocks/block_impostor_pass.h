#pragma once
// The `block_impostors` pass: the camera's impostor atlas.
#include "blocks/block_gpu_buffers.h"
#include "blocks/block_impostor_renderer.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// The camera's impostor atlas as frame-graph resources (the `block_impostors` pass).
struct BlockImpostorAtlas {
    gpu::ResourceHandle depths, sums1, sums2, moments;
    glm::ivec2 size{0};  // texels
};
// A later pass's reads of the atlas, and their binding at the impostor units (gpu_bindings.h).
struct BlockImpostorReads {
    gpu::ResourceHandle depths, sums1, sums2, moments;
};
BlockImpostorReads readBlockImpostors(gpu::PassBuilder& builder, const BlockImpostorAtlas& atlas);
void bindBlockImpostors(const gpu::PassResources& resources, const BlockImpostorReads& reads);

// Adds the `block_impostors` pass: the camera's plan (tile set 0 of `blocks`) rendered into a new
// atlas, or into `into` (imported textures of the plan's size that later frames read again).
BlockImpostorAtlas addBlockImpostorPass(gpu::FrameGraph& graph, const BlockViewPlan& plan, const BlockGpuBuffers& blocks,
                                        const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors,
                                        const BlockImpostorAtlas* into = nullptr);

}  // namespace nimbus::media
