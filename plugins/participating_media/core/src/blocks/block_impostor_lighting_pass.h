#pragma once
// The `block_impostor_lighting` pass (shaders/media/blocks/block_impostor_lighting.*): the light of
// the blocks no mesh comes near, shaded once per two by two texels of the camera's impostor atlas
// instead of once per pixel they cover, for the composite's BLOCK_LIT_IMPOSTOR build to read.
//
// Does not: shade a block a mesh comes near (the composite cuts it at the surface per pixel), or
// an instanced prototype's tile (each instance is lit where it stands).
#include <cstdint>
#include <memory>
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "blocks/block_impostor_pass.h"
#include "blocks/block_seam_mask_pass.h"
#include "common/local_light_programs.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

// Where the composite's lit atlas comes from: shaded this frame, into `keep` when set (a texture the
// technique keeps for later frames, blocks/block_impostor_cache.h) or else a transient one; or an
// earlier frame's read again (`reused` valid), with no lighting pass.
struct LitAtlasSource {
    const gpu::Texture* keep = nullptr;
    gpu::ResourceHandle reused;
};

// Its program (block_impostor_lighting.*), for blocks with lumps the slices do not resolve or not.
gpu::ProgramDesc blockImpostorLightingDesc(bool ownParticles);

class BlockImpostorLightingPass {
public:
    // One draw's ranks (back to front, as the composite draws them) and whether its blocks hold
    // lumps the slices do not resolve (kBlockOwnParticles).
    struct Run {
        BlockRankRun ranks;
        bool ownParticles;
    };
    // The lit atlas: RGBA32F of half the atlas's size, premultiplied radiance and opacity; texels
    // of other blocks' tiles are left unwritten. Written into `keep` when given.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const BlockImpostorAtlas& atlas, std::vector<Run> runs,
                            const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles, const gpu::Texture* keep);

private:
    LocalLightPrograms& programs(bool ownParticles);  // compiled when first asked for

    std::unique_ptr<LocalLightPrograms> programs_[2];
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
