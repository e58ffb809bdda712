#include "blocks/block_lamp_slice_pass.h"

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

BlockLampSlicePass::BlockLampSlicePass() {
    program_ = gpu::compileProgram(
        {.vertex = "media/slices/light_slices.vert", .fragment = "media/slices/light_slices.frag", .defines = {"SLICE_PARTICLE_LIST"}});
}

gpu::ResourceHandle BlockLampSlicePass::add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views,
                                            int resolution, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles) {
    struct Data {
        gpu::ResourceHandle slices;
    };
    const auto& data = graph.addPass<Data>(
        "block_lamp_slices", [&](gpu::PassBuilder& builder, Data& d) { d.slices = builder.write(slices); },
        [this, views, resolution, &blocks, &particles](const gpu::PassResources& r, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            const GLuint program = program_.id();
            for (const SliceView& v : views) {
                if (!v.view.perspective) continue;
                const int texels = sliceTexels(v, resolution);
                bindSliceLayers(fbo.id(), r.id(d.slices), v, false);
                setAdditiveSliceState(texels);
                glUseProgram(program);
                particles.bindParticles();
                blocks.bindLampSliceParticles();
                setParticleSliceUniforms(program, v, texels);
                glBindVertexArray(vertexArray_.id());
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(blocks.lampSliceParticleCount()));
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
