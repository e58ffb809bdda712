#include "raymarch/raymarch_pass.h"

#include <algorithm>

#include "common/frame_blocks.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
constexpr GLint kFragOffsetLocation = 7;  // raymarch.frag uFragOffset
}

RaymarchPass::RaymarchPass() : pass_("media/raymarch/raymarch.frag") {}

RaymarchPass::March RaymarchPass::march(GraphFrame& context, const VoxelGrid& grid, const RaymarchGrid& textures, int maxSteps) {
    if (context.multiple && !multiple_) multiple_ = std::make_unique<gpu::FullscreenPass>("media/raymarch/raymarch.frag", std::vector<std::string>{"MEDIA_MULTIPLE"});
    // The grid relative to the frame origin, in float: the camera is near it, so it stays exact.
    return {.pass = context.multiple ? multiple_.get() : &pass_,
            .context = &context,
            .textures = &textures,
            .corner = glm::vec3(grid.min - context.host.camera.origin),
            .extent = glm::vec3(glm::dvec3(grid.size) * grid.voxel),
            .voxel = static_cast<float>(grid.voxel.x),
            .maxSteps = std::max(maxSteps, 1),
            .rayleigh = grid.rayleigh};
}

void RaymarchPass::draw(const gpu::PassResources& resources, const LitMediaInputs& d, const March& m, GLuint framebuffer, glm::ivec2 size,
                        glm::vec2 scale, glm::vec2 offset, const gpu::PipelineState& state) {
    const GLuint program = m.pass->program();
    m.context->blocks->bind();
    bindLitMediaInputs(resources, d);
    glBindTextureUnit(kVoxelScatteringUnit, m.textures->scattering().id());
    glBindTextureUnit(kVoxelEmissionUnit, m.textures->emission().id());
    glProgramUniform2f(program, 1, scale.x, scale.y);
    glProgramUniform3f(program, 2, m.corner.x, m.corner.y, m.corner.z);
    glProgramUniform3f(program, 3, m.extent.x, m.extent.y, m.extent.z);
    glProgramUniform1f(program, 4, m.voxel);
    glProgramUniform1i(program, 5, m.maxSteps);
    glProgramUniform1i(program, 6, m.rayleigh ? 1 : 0);
    glProgramUniform2f(program, kFragOffsetLocation, offset.x, offset.y);
    m.pass->draw(framebuffer, size, state);
}

gpu::ResourceHandle RaymarchPass::add(gpu::FrameGraph& graph, GraphFrame& context, const March& m, const MediaTarget& target) {
    struct Data : LitMediaInputs {};
    const auto& data = graph.addPass<Data>(
        "media_raymarch", [&](gpu::PassBuilder& builder, Data& d) { declareLitMediaInputs(builder, context, target, d); },
        [m, size = target.size, scale = target.fullResScale](const gpu::PassResources& resources, const Data& d) {
            // Every texel is written once, unblended: (in-scattered radiance, transmittance).
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(resources.id(d.media), GL_RGBA32F);
            draw(resources, d, m, fbo.id(), size, scale, glm::vec2(0.0f), {});
        });
    return data.media;
}

}  // namespace nimbus::media
