#pragma once
// The `media_raymarch_edges` pass: the march again at full resolution where the reduced media
// target has an edge (mixed resolution, upsample/media_edge_stencil_pass.h).
#include "nimbus/media/technique.h"
#include "raymarch/raymarch_pass.h"
#include "upsample/media_edge_stencil_pass.h"

namespace nimbus::media {

// The same march as this frame's `media_raymarch`, into `edges.color` behind its stencil. Returns
// the edge colour.
gpu::ResourceHandle addRaymarchEdges(gpu::FrameGraph& graph, GraphFrame& context, const RaymarchPass::March& march, const EdgeTarget& edges);

}  // namespace nimbus::media
