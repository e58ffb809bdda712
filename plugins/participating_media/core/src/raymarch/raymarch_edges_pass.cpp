// Mixed resolution for raymarch: the rays of the pixels where the reduced target's upsampling meets
// another depth, marched again at full resolution over the edge rect behind its stencil. A
// full-screen pass, so only the marked pixels run the march.
#include "raymarch/raymarch_edges_pass.h"

namespace nimbus::media {

namespace {
// Unblended, as the main march, only where the edge stencil is 1 (read only).
constexpr gpu::PipelineState edgeState() {
    gpu::PipelineState state;
    state.stencil = {.test = true, .compare = GL_EQUAL, .reference = 1, .readMask = 0xFF, .writeMask = 0x00};
    return state;
}
}  // namespace

gpu::ResourceHandle addRaymarchEdges(gpu::FrameGraph& graph, GraphFrame& context, const RaymarchPass::March& march, const EdgeTarget& edges) {
    struct Data : LitMediaInputs {
        gpu::ResourceHandle stencil;
    };
    const auto& data = graph.addPass<Data>(
        "media_raymarch_edges",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.write(edges.color);
            d.stencil = builder.read(edges.stencil);
            d.depth = builder.read(context.sceneDepth);
            if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
            if (context.slices.valid()) d.slices = builder.read(context.slices);
        },
        [march, rect = edges.rect](const gpu::PassResources& r, const Data& d) {
            const gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.media), 0);
            glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, r.id(d.stencil), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            RaymarchPass::draw(r, d, march, fbo.id(), glm::ivec2(rect.z, rect.w), glm::vec2(1.0f), glm::vec2(rect.x, rect.y), edgeState());
        });
    return data.media;
}

}  // namespace nimbus::media
