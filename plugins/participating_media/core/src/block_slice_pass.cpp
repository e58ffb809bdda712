// Blocks mode, light side (seed 000 §2.2): for each light view, the blocks' light impostors, then
// every block spread over the slices by its depth profile (block_slices.frag); a lamp's views add
// the particles of the blocks it sees wide one by one (media/block_partition.h kMaxLampImpostorSpread).
#include <glm/gtc/type_ptr.hpp>

#include "block_passes.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

BlockSlicePass::BlockSlicePass() {
    program_ = gpu::compileProgram({.vertex = "media/block_slices.vert", .fragment = "media/block_slices.frag"});
    particleProgram_ = gpu::compileProgram(
        {.vertex = "media/light_slices.vert", .fragment = "media/light_slices.frag", .defines = {"SLICE_PARTICLE_LIST"}});
}

render::ResourceHandle BlockSlicePass::add(render::FrameGraph& graph, const std::vector<SliceView>& views,
                                           const std::vector<BlockViewPlan>& plans, int resolution, const BlockGpuBuffers& blocks,
                                           const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors) {
    int layers = 0;
    for (std::size_t i = 0; i < views.size(); ++i) layers = std::max(layers, views[i].firstLayer + (views[i].slices + 3) / 4);
    struct Data {
        render::ResourceHandle slices;
        std::vector<render::ResourceHandle> impostors, moments;  // one atlas per view: none is rewritten while queued draws read it
    };
    const auto& data = graph.addPass<Data>(
        "block_light_slices",
        [&](render::PassBuilder& builder, Data& d) {
            d.slices = builder.create("light_slices", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
            for (std::size_t i = 0; i < plans.size(); ++i) {
                const glm::ivec2 size = plans[i].atlasSize;
                d.impostors.push_back(builder.create("block_light_impostors_" + std::to_string(i), {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1}));
                d.moments.push_back(builder.create("block_light_moments_" + std::to_string(i), {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1}));
            }
        },
        [this, views, &plans, resolution, &blocks, &particles, &impostors](const render::PassResources& r, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            const GLuint program = program_.id();
            for (std::size_t i = 0; i < views.size(); ++i) {
                const SliceView& v = views[i];
                impostors.render(plans[i], i + 1, {.depths = r.id(d.impostors[i]), .moments = r.id(d.moments[i])}, blocks, particles);

                bindSliceLayers(fbo.id(), r.id(d.slices), v);
                glViewport(0, 0, resolution, resolution);
                glDisable(GL_DEPTH_TEST);
                glDisable(GL_CULL_FACE);
                glEnable(GL_BLEND);
                glBlendEquation(GL_FUNC_ADD);
                glBlendFunc(GL_ONE, GL_ONE);
                glUseProgram(program);
                blocks.bind(i + 1);
                glBindTextureUnit(5, r.id(d.impostors[i]));
                glBindTextureUnit(6, r.id(d.moments[i]));
                setSliceViewUniforms(program, v, resolution);
                glBindVertexArray(vertexArray_.id());
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(plans[i].tiles.size()));
                if (v.view.perspective && blocks.lampSliceParticleCount() > 0) {
                    const GLuint list = particleProgram_.id();
                    glUseProgram(list);
                    particles.bindParticles();
                    blocks.bindLampSliceParticles();
                    setParticleSliceUniforms(list, v, resolution);
                    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(blocks.lampSliceParticleCount()));
                }
                glBindVertexArray(0);
                glDisable(GL_BLEND);
                unbindSliceLayers(fbo.id(), v);
            }
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.slices;
}

}  // namespace nimbus::media
