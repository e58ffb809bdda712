// Mixed resolution: the reduced texels where a mesh's surface lies inside a particle, marked in the
// depth they used (shaders/media/upsample/seam_marks.frag).
#include "upsample/media_seam_marks_pass.h"

#include <algorithm>

#include "common/frame_blocks.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/media/medium_footprint.h"

namespace nimbus::media {

namespace {
constexpr GLint kFullResScaleLocation = 1;  // seam_marks.frag uFullResScale
// Every mark writes the same value, so overlapping billboards need no blending or order.
constexpr gpu::PipelineState kOverwrite{};
}  // namespace

MediaSeamMarksPass::MediaSeamMarksPass()
    : program_(gpu::compileProgram({.vertex = "media/upsample/seam_marks.vert", .fragment = "media/upsample/seam_marks.frag"})) {}

gpu::ResourceHandle MediaSeamMarksPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                                            std::vector<std::uint32_t> particles, gpu::ResourceHandle depthUsed, const MediaTarget& target) {
    if (particles.empty() || !context.color.valid()) return depthUsed;
    const std::size_t bytes = particles.size() * sizeof(std::uint32_t);
    if (!particles_ || capacity_ < bytes) {
        capacity_ = std::max(bytes, capacity_ * 3 / 2);
        particles_ = gpu::createBuffer(capacity_);
    }
    struct Data {
        gpu::ResourceHandle depthUsed, scene, media;
    };
    const auto& data = graph.addPass<Data>(
        "media_seam_marks",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.depthUsed = builder.write(depthUsed);
            d.scene = builder.read(context.sceneDepth);
            d.media = builder.read(context.color);
        },
        [this, &context, &buffer, particles = std::move(particles), target](const gpu::PassResources& r, const Data& d) {
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.depthUsed), GL_R32F);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, target.size.x, target.size.y);
            glNamedBufferSubData(particles_.id(), 0, static_cast<GLsizeiptr>(particles.size() * sizeof(std::uint32_t)), particles.data());
            gpu::applyPipeline(kOverwrite);
            glUseProgram(program_.id());
            context.blocks->bind();
            buffer.bindParticles();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSeamParticlesBinding, particles_.id());
            glBindTextureUnit(kSceneDepthUnit, r.id(d.scene));
            glBindTextureUnit(kReducedMediaUnit, r.id(d.media));
            glProgramUniform2f(program_.id(), kFullResScaleLocation, target.fullResScale.x, target.fullResScale.y);
            glBindVertexArray(vertexArray_.id());
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(particles.size()));
        });
    return data.depthUsed;
}

std::vector<std::uint32_t> particlesCutByMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles) {
    std::vector<std::uint32_t> out;
    if (meshes.empty()) return out;
    const std::vector<std::uint8_t> near = particlesNearMeshes(meshes, particles, 1.0);
    for (std::size_t i = 0; i < near.size(); ++i)
        if (near[i] != 0) out.push_back(static_cast<std::uint32_t>(i));
    return out;
}

}  // namespace nimbus::media
