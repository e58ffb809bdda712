#pragma once
// The `media_block_edges` pass: mixed resolution for blocks mode (block_composite.* again).
#include "blocks/block_composite_pass.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

// At the pixels where the reduced target's upsampling meets another depth (a mesh's silhouette over
// the medium, a thin mesh inside it), the blocks are composited again at full resolution from this
// frame's atlas and its light (`composite`'s, after its add), behind the edges' stencil. Returns
// the edges' colour.
gpu::ResourceHandle addBlockCompositeEdges(gpu::FrameGraph& graph, GraphFrame& context, BlockCompositePass& composite,
                                           const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles, const EdgeTarget& edges);

}  // namespace nimbus::media
