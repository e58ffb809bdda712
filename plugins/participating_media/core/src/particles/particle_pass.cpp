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
    const int w = target.size.x, h = target.size.y;
    if (!shading.layerLight && !pointLight_)
        pointLight_ = std::make_unique<LocalLightPrograms>(particlesDesc(false));
    const gpu::Program& program = (shading.layerLight ? layerLight_ : *pointLight_).forLights(context.host.lights);
    const auto& data = graph.addPass<Data>(
        "media_particles",
        [&](gpu::PassBuilder& builder, Data& d) {
            declareLitMediaInputs(builder, context, target, d);
        },
        [this, &program, &context, &buffer, shading, w, h, scale = target.fullResScale](const gpu::PassResources& resources,
                                                                                  const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, resources.id(d.media), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, w, h);
            const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // no radiance, full transmittance
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);

            glUseProgram(program.id());
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            buffer.bindLampNeighbourhoods();
            bindLitMediaInputs(resources, d);
            glProgramUniform1i(program.id(), 0, shading.softParticles ? 1 : 0);
            glProgramUniform2f(program.id(), 1, scale.x, scale.y);
            glDisable(GL_DEPTH_TEST);  // the fragment shader clips against scene depth itself
            glDisable(GL_CULL_FACE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
            glBindVertexArray(0);
            glDisable(GL_BLEND);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.media;
}

}  // namespace nimbus::media
