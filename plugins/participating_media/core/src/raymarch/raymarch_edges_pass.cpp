// Mixed resolution for raymarch: the rays of the pixels where the reduced target's upsampling meets
// another depth, marched again at full resolution over the edge rect behind its stencil. A
// full-screen pass, so only the marked pixels run the march.
#include "raymarch/raymarch_edges_pass.h"

namespace nimbus::media {

gpu::ResourceHandle addRaymarchEdges(gpu::FrameGraph& graph, GraphFrame& context, const RaymarchPass::March& march, const EdgeTarget& edges) {
    struct Data : LitMediaInputs {
        gpu::ResourceHandle stencil;
    };
    const auto& data = graph.addPass<Data>(
        "media_raymarch_edges",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.write(edges.color);
            d.stencil = builder.read(edges.stencil);
            readLitMediaInputs(builder, context, d);
        },
        [march, rect = edges.rect](const gpu::PassResources& r, const Data& d) {
            // Unblended, as the main march.
            const gpu::Framebuffer fbo = edgeFramebuffer(r.id(d.media), r.id(d.stencil));
            RaymarchPass::draw(r, d, march, fbo.id(), glm::ivec2(rect.z, rect.w), glm::vec2(1.0f), glm::vec2(rect.x, rect.y), onEdges({}));
        });
    return data.media;
}

}  // namespace nimbus::media
