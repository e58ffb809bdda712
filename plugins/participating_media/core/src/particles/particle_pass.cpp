// `particles` mode: camera-facing billboards, sorted back to front, blended premultiplied into the
// media target. rgb accumulates in-scattered radiance, alpha the view transmittance (cleared to 1,
// multiplied by 1 − α per particle), so the compose pass needs no extra state.
#include "particles/particle_pass.h"

#include "common/frame_blocks.h"
#include "common/lit_media_inputs.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {


ParticlePass::ParticlePass() : layerLight_(particlesDesc(true)) {}

gpu::ProgramDesc particlesDesc(bool layerLight) {
    gpu::ProgramDesc desc{.vertex = "media/particles/particles.vert", .fragment = "media/particles/particles.frag"};
    if (layerLight) desc.defines.push_back("MEDIA_LAYER_LIGHT");
    return desc;
}

gpu::ResourceHandle ParticlePass::add(gpu::FrameGraph& graph, GraphFrame& context,
                                         const ParticleGpuBuffer& buffer, ParticleShading shading, const MediaTarget& target) {
    struct Data : LitMediaInputs {};
    if (!shading.layerLight && !pointLight_)
        pointLight_ = std::make_unique<LocalLightPrograms>(particlesDesc(false));
    const gpu::Program& program = (shading.layerLight ? layerLight_ : *pointLight_).forLights(context.host.lights, context.multiple);
    const auto& data = graph.addPass<Data>(
        "media_particles",
        [&](gpu::PassBuilder& builder, Data& d) {
            declareLitMediaInputs(builder, context, target, d);
        },
        [this, &program, &context, &buffer, shading, target, scale = target.fullResScale](const gpu::PassResources& resources,
                                                                                         const Data& d) {
            const gpu::Framebuffer fbo = bindMediaTarget(resources.id(d.media), target);

            glUseProgram(program.id());
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            buffer.bindLampNeighbourhoods();
            bindLitMediaInputs(resources, d);
            glProgramUniform1i(program.id(), 0, shading.softParticles ? 1 : 0);
            glProgramUniform2f(program.id(), 1, scale.x, scale.y);
            gpu::applyPipeline(mediaOver(target));
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
        });
    return data.media;
}

}  // namespace nimbus::media
