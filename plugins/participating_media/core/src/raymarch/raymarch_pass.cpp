#include "raymarch/raymarch_pass.h"

#include <algorithm>

#include "common/frame_blocks.h"
#include "common/lit_media_inputs.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

RaymarchPass::RaymarchPass() : pass_("media/raymarch/raymarch.frag") {}

gpu::ResourceHandle RaymarchPass::add(gpu::FrameGraph& graph, GraphFrame& context, const VoxelGrid& grid, const RaymarchGrid& textures,
                                      int maxSteps, const MediaTarget& target) {
    struct Data : LitMediaInputs {};
    if (context.multiple && !multiple_) multiple_ = std::make_unique<gpu::FullscreenPass>("media/raymarch/raymarch.frag", std::vector<std::string>{"MEDIA_MULTIPLE"});
    const gpu::FullscreenPass& pass = context.multiple ? *multiple_ : pass_;
    const int w = target.size.x, h = target.size.y;
    // The grid relative to the frame origin, in float: the camera is near it, so it stays exact.
    const glm::vec3 corner(grid.min - context.host.camera.origin);
    const glm::vec3 extent(glm::dvec3(grid.size) * grid.voxel);
    const auto& data = graph.addPass<Data>(
        "media_raymarch",
        [&](gpu::PassBuilder& builder, Data& d) {
            declareLitMediaInputs(builder, context, target, d);
        },
        [&pass, &context, &textures, w, h, corner, extent, maxSteps, voxel = static_cast<float>(grid.voxel.x), rayleigh = grid.rayleigh,
         scale = target.fullResScale](const gpu::PassResources& resources, const Data& d) {
            // Every texel is written once, unblended: (in-scattered radiance, transmittance).
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(resources.id(d.media), GL_RGBA32F);
            const GLuint program = pass.program();
            context.blocks->bind();
            bindLitMediaInputs(resources, d);
            glBindTextureUnit(kVoxelScatteringUnit, textures.scattering().id());
            glBindTextureUnit(kVoxelEmissionUnit, textures.emission().id());
            glProgramUniform2f(program, 1, scale.x, scale.y);
            glProgramUniform3f(program, 2, corner.x, corner.y, corner.z);
            glProgramUniform3f(program, 3, extent.x, extent.y, extent.z);
            glProgramUniform1f(program, 4, voxel);
            glProgramUniform1i(program, 5, std::max(maxSteps, 1));
            glProgramUniform1i(program, 6, rayleigh ? 1 : 0);
            pass.draw(fbo.id(), {w, h});
        });
    return data.media;
}

}  // namespace nimbus::media
