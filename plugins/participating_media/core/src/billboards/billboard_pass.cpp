// `billboards` mode, the yardstick of docs/PERFORMANCE.md: what a typical engine ships. Sorted
// camera-facing sprites, lit once per particle at the vertices with no volumetric self-shadowing
// and no mesh shadows on the particles, one sprite fetch per fragment and soft particles
// (shaders/media/billboards.*). Not a feature to tune: a measured baseline.
#include "billboards/billboard_pass.h"

#include "common/kernel_table.h"
#include "common/lit_media_inputs.h"
#include "common/frame_blocks.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

BillboardPass::BillboardPass()
    : program_(gpu::compileProgram({.vertex = "media/billboards/billboards.vert", .fragment = "media/billboards/billboards.frag"})),
      kernelTable_(createKernelTable()) {}

gpu::ResourceHandle BillboardPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                                          const MediaTarget& target) {
    struct Data {
        gpu::ResourceHandle media, depth;
    };
    const auto& data = graph.addPass<Data>(
        "media_billboards",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = declareMediaTarget(builder, target);
            d.depth = builder.read(context.sceneDepth);
        },
        [this, &context, &buffer, target, scale = target.fullResScale](const gpu::PassResources& resources, const Data& d) {
            const gpu::Framebuffer fbo = bindMediaTarget(resources.id(d.media), target);
            glUseProgram(program_.id());
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            glBindTextureUnit(kSceneDepthUnit, resources.id(d.depth));
            glBindTextureUnit(kKernelTableUnit, kernelTable_.id());
            glProgramUniform2f(program_.id(), 1, scale.x, scale.y);
            gpu::applyPipeline(mediaOver(target));
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
        });
    return data.media;
}

}  // namespace nimbus::media
