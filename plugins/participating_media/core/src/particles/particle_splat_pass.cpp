// Fast particles: the billboards of `particles` mode in the same back-to-front order, with the
// source per vertex from the lighting pass and per fragment only the kernel's opacity from the
// pre-integrated table (shaders/media/particle_splats.*). Blends exactly as ParticlePass does.
#include "particles/particle_splat_pass.h"

#include "common/kernel_table.h"
#include "common/lit_media_inputs.h"
#include "common/frame_blocks.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

namespace {
constexpr GLint kFragmentSunLocation = 7;    // particle_light_layout.glsl uFragmentSun
constexpr GLint kFragmentLampsLocation = 8;  // particle_light_layout.glsl uFragmentLamps
}

ParticleSplatPass::ParticleSplatPass() : kernelTable_(createKernelTable()) {}

const gpu::Program& ParticleSplatPass::program(bool eyeInside, bool lamps, bool constant) {
    gpu::Program& p = programs_[(eyeInside ? 1 : 0) + (lamps ? 2 : 0) + (constant ? 4 : 0)];
    if (!p) p = gpu::compileProgram(particleSplatDesc(eyeInside, lamps, constant));
    return p;
}

gpu::ProgramDesc particleSplatDesc(bool eyeInside, bool lamps, bool constant) {
    gpu::ProgramDesc desc{.vertex = "media/particles/particle_splats.vert", .fragment = "media/particles/particle_splats.frag"};
    if (eyeInside) desc.defines.push_back("MEDIA_EYE_INSIDE");
    if (lamps) desc.defines.push_back("MEDIA_FRAGMENT_LAMPS");
    if (constant) desc.defines.push_back("SPLAT_CONSTANT");
    return desc;
}

gpu::ResourceHandle ParticleSplatPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                                              const ParticleLightingPass& lighting, bool eyeInside, bool constant,
                                              const FragmentLamps& lamps, const MediaTarget& target) {
    const gpu::Program& program = this->program(eyeInside, lamps.lamps[0] >= 0, constant);
    struct Data {
        gpu::ResourceHandle media, depth, slices, shadowMap;
    };
    const int w = target.size.x, h = target.size.y;
    const auto& data = graph.addPass<Data>(
        "media_particle_splats",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.create(target.name, {GL_TEXTURE_2D, GL_RGBA32F, w, h, 1, 1});
            d.depth = builder.read(context.sceneDepth);
            if (lamps.lamps[0] >= 0 && context.slices.valid()) d.slices = builder.read(context.slices);
            if (lamps.lamps[0] >= 0 && context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
        },
        [this, &program, &context, &buffer, &lighting, lamps, w, h, scale = target.fullResScale](const gpu::PassResources& resources,
                                                                                          const Data& d) {
            const gpu::Framebuffer fbo = bindClearedMediaTarget(resources.id(d.media), {w, h});
            glUseProgram(program.id());
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            lighting.bind();
            glBindTextureUnit(kSceneDepthUnit, resources.id(d.depth));
            glBindTextureUnit(kKernelTableUnit, kernelTable_.id());
            if (d.slices.valid()) glBindTextureUnit(kSlicesUnit, resources.id(d.slices));
            if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, resources.id(d.shadowMap));
            glProgramUniform2f(program.id(), 1, scale.x, scale.y);
            glProgramUniform1i(program.id(), kFragmentSunLocation, lamps.sun);
            if (lamps.lamps[0] >= 0) glProgramUniform1iv(program.id(), kFragmentLampsLocation, kMaxFragmentLamps, lamps.lamps.data());
            gpu::applyPipeline(kMediaOver);
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
        });
    return data.media;
}

}  // namespace nimbus::media
