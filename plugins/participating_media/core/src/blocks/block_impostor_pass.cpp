#include "blocks/block_impostor_pass.h"

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

BlockImpostorReads readBlockImpostors(gpu::PassBuilder& builder, const BlockImpostorAtlas& atlas) {
    return {builder.read(atlas.depths), builder.read(atlas.sums1), builder.read(atlas.sums2), builder.read(atlas.moments)};
}

void bindBlockImpostors(const gpu::PassResources& resources, const BlockImpostorReads& reads) {
    glBindTextureUnit(kImpostorDepthsUnit, resources.id(reads.depths));
    glBindTextureUnit(kImpostorSums1Unit, resources.id(reads.sums1));
    glBindTextureUnit(kImpostorSums2Unit, resources.id(reads.sums2));
    glBindTextureUnit(kImpostorMomentsUnit, resources.id(reads.moments));
}

BlockImpostorAtlas addBlockImpostorPass(gpu::FrameGraph& graph, const BlockViewPlan& plan, const BlockGpuBuffers& blocks,
                                        const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors,
                                        const BlockImpostorAtlas* into) {
    const glm::ivec2 atlas = plan.atlasSize;
    return graph.addPass<BlockImpostorAtlas>(
        "block_impostors",
        [&](gpu::PassBuilder& builder, BlockImpostorAtlas& d) {
            d.size = atlas;
            if (into != nullptr) {
                d.depths = builder.write(into->depths);
                d.sums1 = builder.write(into->sums1);
                d.sums2 = builder.write(into->sums2);
                d.moments = builder.write(into->moments);
                return;
            }
            d.depths = builder.create("block_impostor_depths", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums1 = builder.create("block_impostor_sums1", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums2 = builder.create("block_impostor_sums2", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.moments = builder.create("block_impostor_moments", {GL_TEXTURE_2D, GL_RG32F, atlas.x, atlas.y, 1, 1});
        },
        [&plan, &blocks, &particles, &impostors](const gpu::PassResources& r, const BlockImpostorAtlas& d) {
            impostors.render(plan, 0,
                             {.depths = r.id(d.depths), .sums1 = r.id(d.sums1), .sums2 = r.id(d.sums2), .moments = r.id(d.moments)},
                             blocks, particles);
        });
}

}  // namespace nimbus::media
