// Mixed resolution for blocks mode (block_composite_edges_pass.h). The composite neither discards
// before its stencil test nor writes depth, so the test runs before the fragment shader and only
// the marked pixels are shaded.
#include "blocks/block_composite_edges_pass.h"

#include "upsample/media_edge_stencil_pass.h"

namespace nimbus::media {

gpu::ResourceHandle addBlockCompositeEdges(gpu::FrameGraph& graph, GraphFrame& context, BlockCompositePass& composite,
                                           const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles, const EdgeTarget& edges) {
    struct Data : BlockCompositePass::Inputs {
        gpu::ResourceHandle stencil;
    };
    const auto& data = graph.addPass<Data>(
        "media_block_edges",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.write(edges.color);
            d.stencil = builder.read(edges.stencil);
            readLitMediaInputs(builder, context, d);
            composite.readInputs(builder, d);
        },
        [&composite, &context, &blocks, &particles, draws = composite.edgeDraws(context.host.lights, context.multiple),
         rect = edges.rect](const gpu::PassResources& r, const Data& d) {
            const gpu::View& v = context.host.camera;
            const gpu::Framebuffer fbo = bindEdgeFramebuffer(r.id(d.media), r.id(d.stencil), rect, {v.width, v.height});
            composite.bindInputs(r, d, context, blocks, particles);
            const gpu::PipelineState state = onEdges(kMediaOver);
            composite.drawRuns(draws, glm::vec2(1.0f), glm::vec2(rect.x, rect.y), &state);
        });
    return data.media;
}

}  // namespace nimbus::media
