#pragma once
// The `block_lamp_slices` pass: a lamp's slice views add the particles of the blocks it sees wide
// one by one (planning: blocksSeenWideFromLamps), as particles mode draws them
// (shaders/media/light_slices.* with SLICE_PARTICLE_LIST), over what `block_light_slices` spread.
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

class BlockLampSlicePass {
public:
    BlockLampSlicePass();
    // Adds to `slices` in the perspective views; returns its new version.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views, int resolution,
                            const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
