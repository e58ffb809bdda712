#pragma once
// The `media_particle_splat_edges` pass: the splats again at full resolution where the reduced
// media target has an edge (mixed resolution, upsample/media_edge_stencil_pass.h).
#include "particles/particle_splat_pass.h"
#include "upsample/media_edge_stencil_pass.h"

namespace nimbus::media {

// The same draws as `splats.add` made this frame (the same lighting, variant, flags and lamps),
// of the particles `meets` flags (one per particle: its billboard meets edges.rect), into
// `edges.color` behind its stencil. Returns the edge colour.
struct SplatEdgeDraw {
    SplatVariant variant;
    std::vector<std::uint8_t> flags, meets;
    FragmentLamps lamps;
};
gpu::ResourceHandle addParticleSplatEdges(gpu::FrameGraph& graph, GraphFrame& context, ParticleSplatPass& splats, const ParticleGpuBuffer& buffer,
                                          const ParticleLightingPass& lighting, SplatEdgeDraw draw, const EdgeTarget& edges);

}  // namespace nimbus::media
