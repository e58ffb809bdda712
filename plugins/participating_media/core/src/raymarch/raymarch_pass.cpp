#include "raymarch/raymarch_pass.h"

#include <algorithm>

#include "common/frame_blocks.h"
#include "common/lit_media_inputs.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

RaymarchPass::RaymarchPass() : pass_("media/raymarch/raymarch.frag") {}

void RaymarchPass::upload(const VoxelGrid& grid) {
    for (gpu::Texture* texture : {&scattering_, &emission_})
        if (!*texture || texture->desc().width != grid.size.x || texture->desc().height != grid.size.y ||
            texture->desc().depth != grid.size.z) {
            *texture = gpu::Texture({.target = GL_TEXTURE_3D, .format = GL_RGBA32F, .width = grid.size.x, .height = grid.size.y,
                                     .depth = grid.size.z});
            glTextureParameteri(texture->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(texture->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTextureParameteri(texture->id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
            glTextureParameteri(texture->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(texture->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        }
    glTextureSubImage3D(scattering_.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT, grid.scattering.data());
    glTextureSubImage3D(emission_.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT, grid.emission.data());
}

gpu::ResourceHandle RaymarchPass::add(gpu::FrameGraph& graph, GraphFrame& context, const VoxelGrid& grid, int maxSteps,
                                      const MediaTarget& target) {
    struct Data : LitMediaInputs {};
    upload(grid);
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
        [this, &pass, &context, w, h, corner, extent, maxSteps, voxel = static_cast<float>(grid.voxel.x), rayleigh = grid.rayleigh,
         scale = target.fullResScale](const gpu::PassResources& resources, const Data& d) {
            // Every texel is written once, unblended: (in-scattered radiance, transmittance).
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(resources.id(d.media), GL_RGBA32F);
            const GLuint program = pass.program();
            context.blocks->bind();
            bindLitMediaInputs(resources, d);
            glBindTextureUnit(kVoxelScatteringUnit, scattering_.id());
            glBindTextureUnit(kVoxelEmissionUnit, emission_.id());
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
