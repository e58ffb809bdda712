#pragma once
// The `block_seam_mask` pass (shaders/media/blocks/block_seam_mask.frag, block_seam_stencil.frag).
#include <vector>

#include "blocks/block_gpu_buffers.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

// Consecutive ranks of the camera's back-to-front order, drawn as one instanced draw.
struct BlockRankRun {
    GLint first = 0;
    GLsizei count = 0;
};

// Media texels per seam mask texel, per axis, for a media target of `size`: about a 48th of its
// shorter side, at least 4. The exact shading reaches half a cell past the texels where a mesh lies
// in the medium and fades out over the next cell (shaders/media/blocks/block_seam.glsl seamWeight), so that
// fade is as wide a share of the image at any resolution (docs/design-notes.md).
int seamMaskCell(glm::ivec2 size);

// The seam mask (shaders/media/blocks/block_seam.glsl): one R8 texel per cell of seamMaskCell² texels of
// the media target, 1 where, at one of them, the opaque surface lies among the particles of a block
// drawn by `runs` (within its impostor's [front − reach, back + reach]), i.e. where a mesh is seen
// inside the medium. Draws the blocks' rectangles widened by a cell, one fragment per cell.
//
// Does not: widen the mask or smooth its edge (block_seam.glsl seamWeight does, where it is read).
class BlockSeamMaskPass {
public:
    BlockSeamMaskPass();
    // R8, one texel per cell.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, std::vector<BlockRankRun> runs, const BlockGpuBuffers& blocks,
               gpu::ResourceHandle impostorDepths, const MediaTarget& target, int cell);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
