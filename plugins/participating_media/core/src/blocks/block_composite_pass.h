#pragma once
// The `block_composite` pass (shaders/media/block_composite.*).
#include <cstdint>
#include <memory>
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "blocks/block_impostor_lighting_pass.h"
#include "blocks/block_impostor_pass.h"
#include "blocks/block_seam_mask_pass.h"
#include "blocks/block_seam_stencil_pass.h"
#include "common/lit_media_inputs.h"
#include "common/local_light_programs.h"
#include "common/particle_buffer.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"
#include "planning/block_classification.h"

namespace nimbus::media {

// The camera's impostor atlas and where its light comes from.
struct CameraImpostors {
    BlockImpostorAtlas atlas;
    LitAtlasSource lit;
};

// Camera: impostors into an atlas, then blocks composited back to front into the media target.
// The composite program (block_composite.*) for a BlockCompositeBuild.
gpu::ProgramDesc blockCompositeDesc(std::uint8_t build);

class BlockCompositePass {
public:
    BlockCompositePass();
    // The camera's plan is tile set 0 of `blocks`; `builds`: each block's BlockCompositeBuild bits.
    // `seamOnly` (block_shading=seam): the BLOCK_EXACT_SHADING blocks are shaded exactly only near the
    // texels where a mesh lies among the particles of the blocks a mesh comes near (BlockSeamMaskPass),
    // and smoothly elsewhere, blended over a mask cell (block_seam.glsl seamWeight).
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const CameraImpostors& impostors,
                               const std::vector<std::uint32_t>& backToFront, const std::vector<std::uint8_t>& builds,
                               bool seamOnly, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                               const MediaTarget& target);

    // One draw of the composite: its ranks, program and seam part (block_composite.frag uSeamPart).
    struct Draw {
        BlockRankRun ranks;
        const gpu::Program* program;
        GLint seamPart;
    };
    // Consecutive ranks that want the same build, drawn in order.
    struct Run {
        BlockRankRun ranks;
        std::uint8_t build;
    };
    struct Seam {
        gpu::ResourceHandle mask, stencil;
    };
    // What its draws read.
    struct Inputs : LitMediaInputs {
        BlockImpostorReads atlas;
        gpu::ResourceHandle seamMask, seamStencil, lit;
    };
    // This frame's, for its edges (block_composite_edges_pass.cpp): the atlas, its light and runs.
    struct Frame {
        BlockImpostorAtlas atlas;
        gpu::ResourceHandle lit;
        std::vector<Run> runs;
    };
    // The draws of this frame's edges, planned (and their programs compiled) only when drawn:
    // they have no seam mask, so a run shaded exactly near a mesh is shaded exactly there.
    std::vector<Draw> edgeDraws(const std::vector<Light>& lights, bool multiple);
    void readInputs(gpu::PassBuilder& builder, Inputs& d) const;  // the atlas and its light
    void bindInputs(const gpu::PassResources& r, const Inputs& d, const GraphFrame& context, const BlockGpuBuffers& blocks,
                    const ParticleGpuBuffer& particles) const;
    void drawRuns(const std::vector<Draw>& draws, glm::vec2 scale, glm::vec2 offset, const gpu::PipelineState* edges) const;

private:
    LocalLightPrograms& programs(std::uint8_t build);  // compiled when first asked for
    Seam addSeamPasses(gpu::FrameGraph& graph, GraphFrame& context, const std::vector<Run>& runs, bool seamOnly,
                       const BlockGpuBuffers& blocks, const BlockImpostorAtlas& atlas, const MediaTarget& target, int cell);
    gpu::ResourceHandle addLighting(gpu::FrameGraph& graph, GraphFrame& context, const std::vector<Run>& runs,
                                    const CameraImpostors& impostors, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles);
    std::vector<Draw> planDraws(const std::vector<Run>& runs, bool seamOnly, bool seam, const std::vector<Light>& lights, bool multiple);

    std::unique_ptr<LocalLightPrograms> programs_[16];  // by BlockCompositeBuild bits
    std::unique_ptr<BlockSeamMaskPass> seamMask_;        // made when a frame first needs them
    std::unique_ptr<BlockSeamStencilPass> seamStencil_;
    std::unique_ptr<BlockImpostorLightingPass> lighting_;
    Frame frame_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
