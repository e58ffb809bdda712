// Blocks mode, camera side: the view impostors of every block, then the blocks composited back to
// front over their screen rectangles (shaders/media/block_composite.*).
#include "block_passes.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"

namespace nimbus::media {

inline constexpr GLuint kShadowDepthUnit = 4;
inline constexpr GLuint kImpostorDepthsUnit = 5;

BlockCompositePass::BlockCompositePass()
    : programs_({.vertex = "media/block_composite.vert", .fragment = "media/block_composite.frag"}) {}

render::ResourceHandle BlockCompositePass::add(render::FrameGraph& graph, render::FrameContext& context, const BlockViewPlan& plan,
                                               const std::vector<std::uint32_t>& backToFront, const BlockGpuBuffers& blocks,
                                               const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors,
                                               const MediaTarget& target) {
    struct Impostors {
        render::ResourceHandle depths, sums1, sums2, moments;
    };
    const glm::ivec2 atlas = plan.atlasSize;
    const auto& made = graph.addPass<Impostors>(
        "block_impostors",
        [&](render::PassBuilder& builder, Impostors& d) {
            d.depths = builder.create("block_impostor_depths", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums1 = builder.create("block_impostor_sums1", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums2 = builder.create("block_impostor_sums2", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.moments = builder.create("block_impostor_moments", {GL_TEXTURE_2D, GL_RG32F, atlas.x, atlas.y, 1, 1});
        },
        [&plan, &blocks, &particles, &impostors](const render::PassResources& r, const Impostors& d) {
            impostors.render(plan, 0,
                             {.depths = r.id(d.depths), .sums1 = r.id(d.sums1), .sums2 = r.id(d.sums2), .moments = r.id(d.moments)},
                             blocks, particles);
        });

    struct Composite {
        render::ResourceHandle media, depth, shadowMap, slices, depths, sums1, sums2, moments;
    };
    const int w = target.size.x, h = target.size.y;
    const gpu::Program& program = programs_.forLights(context.input.lights);
    const auto& data = graph.addPass<Composite>(
        "media_blocks",
        [&](render::PassBuilder& builder, Composite& d) {
            d.media = builder.create(target.name, {GL_TEXTURE_2D, GL_RGBA32F, w, h, 1, 1});
            d.depth = builder.read(context.sceneDepth);
            if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
            if (context.transmittanceSlices.valid()) d.slices = builder.read(context.transmittanceSlices);
            d.depths = builder.read(made.depths);
            d.sums1 = builder.read(made.sums1);
            d.sums2 = builder.read(made.sums2);
            d.moments = builder.read(made.moments);
        },
        [this, &program, &context, &backToFront, &blocks, &particles, w, h, scale = target.fullResScale](const render::PassResources& r,
                                                                                            const Composite& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.media), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, w, h);
            const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
            glUseProgram(program.id());
            glProgramUniform2f(program.id(), 1, scale.x, scale.y);
            context.frameData->bind();
            blocks.bind(0);
            particles.bindParticles();  // the listed particles around each lamp (lamp_neighbourhood.glsl)
            particles.bindLampNeighbourhoods();
            glBindTextureUnit(render::kSceneDepthUnit, r.id(d.depth));
            if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, r.id(d.shadowMap));
            if (d.slices.valid()) glBindTextureUnit(render::kTransmittanceUnit, r.id(d.slices));
            glBindTextureUnit(kImpostorDepthsUnit, r.id(d.depths));
            glBindTextureUnit(kImpostorDepthsUnit + 1, r.id(d.sums1));
            glBindTextureUnit(kImpostorDepthsUnit + 2, r.id(d.sums2));
            glBindTextureUnit(kImpostorDepthsUnit + 3, r.id(d.moments));
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_CULL_FACE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(backToFront.size()));
            glBindVertexArray(0);
            glDisable(GL_BLEND);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.media;
}

}  // namespace nimbus::media
