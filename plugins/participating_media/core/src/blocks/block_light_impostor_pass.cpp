#include "blocks/block_light_impostor_pass.h"

#include <string>

namespace nimbus::media {

BlockLightImpostors addBlockLightImpostorPass(gpu::FrameGraph& graph, const std::vector<BlockViewPlan>& plans,
                                              const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                                              const BlockImpostorRenderer& impostors) {
    const auto& data = graph.addPass<BlockLightImpostors>(
        "block_light_impostors",
        [&](gpu::PassBuilder& builder, BlockLightImpostors& d) {
            for (std::size_t i = 0; i < plans.size(); ++i) {
                const glm::ivec2 size = plans[i].atlasSize;
                d.depths.push_back(builder.create("block_light_impostors_" + std::to_string(i), {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1}));
                d.moments.push_back(builder.create("block_light_moments_" + std::to_string(i), {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1}));
            }
        },
        [&plans, &blocks, &particles, &impostors](const gpu::PassResources& r, const BlockLightImpostors& d) {
            for (std::size_t i = 0; i < plans.size(); ++i)
                impostors.render(plans[i], i + 1, {.depths = r.id(d.depths[i]), .moments = r.id(d.moments[i])}, blocks, particles);
        });
    return data;
}

}  // namespace nimbus::media
