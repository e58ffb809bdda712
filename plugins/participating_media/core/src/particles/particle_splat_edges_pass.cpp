// Mixed resolution for the per-particle tiers: at the pixels where the reduced target's upsampling
// meets another depth (a mesh's silhouette over the medium, a thin mesh inside it), the splats are
// drawn again at full resolution. The stencil test runs before the fragment shader (the splats
// neither discard nor write depth), so the particles cost only the pixels marked.
#include "particles/particle_splat_edges_pass.h"

#include "common/lit_media_inputs.h"

namespace nimbus::media {

gpu::ResourceHandle addParticleSplatEdges(gpu::FrameGraph& graph, GraphFrame& context, ParticleSplatPass& splats, const ParticleGpuBuffer& buffer,
                                          const ParticleLightingPass& lighting, SplatEdgeDraw draw, const EdgeTarget& edges) {
    struct Data : ParticleSplatPass::SplatInputs {
        gpu::ResourceHandle stencil;
    };
    const auto& data = graph.addPass<Data>(
        "media_particle_splat_edges",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.write(edges.color);
            d.stencil = builder.read(edges.stencil);
            ParticleSplatPass::declareInputs(builder, context, draw.variant, draw.lamps, d);
        },
        [&splats, draw = std::move(draw), &context, &buffer, &lighting, rect = edges.rect](const gpu::PassResources& r, const Data& d) {
            const gpu::View& v = context.host.camera;
            const gpu::Framebuffer fbo = bindEdgeFramebuffer(r.id(d.media), r.id(d.stencil), rect, {v.width, v.height});
            // The ranks of the particles that reach the rect, in draw order (known only now: the
            // upload pass sorted it); the others would cost their vertices and clipped quads.
            std::vector<std::uint32_t> ranks;
            const std::vector<std::uint32_t>& order = buffer.order();
            for (std::uint32_t rank = 0; rank < order.size(); ++rank)
                if (draw.meets[order[rank]] != 0) ranks.push_back(rank);
            if (ranks.empty()) return;
            splats.draw(r, d,
                        {.context = context, .buffer = buffer, .lighting = lighting, .variant = draw.variant, .flags = draw.flags, .lamps = draw.lamps},
                        glm::vec2(1.0f), onEdges(kMediaOver), glm::vec2(rect.x, rect.y), ranks);
        });
    return data.media;
}

}  // namespace nimbus::media
