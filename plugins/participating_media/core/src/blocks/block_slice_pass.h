#pragma once
// The `block_light_slices` pass (shaders/media/block_slices.*).
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "blocks/block_light_impostor_pass.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "planning/block_view_plan.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Light slices from blocks: in each light view, each block spread over the slices from its light
// impostor (block_light_impostors).
class BlockSlicePass {
public:
    BlockSlicePass();
    // The slice array every view's layers fit in, `resolution` texels a side.
    static gpu::TextureDesc sliceDesc(const std::vector<SliceView>& views, int resolution);
    // Light view i's plan is tile set i + 1 of `blocks`. Into `keep` (of `desc`) when given: a
    // texture later frames read again (blocks/block_impostor_cache.h).
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, const std::vector<BlockViewPlan>& plans,
                            const BlockLightImpostors& impostors, const gpu::TextureDesc& desc, const BlockGpuBuffers& blocks,
                            const gpu::Texture* keep = nullptr);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
