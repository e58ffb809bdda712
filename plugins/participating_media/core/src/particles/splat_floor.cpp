#include "particles/splat_floor.h"

#include <chrono>
#include <vector>

#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/gpu/pipeline_state.h"

namespace nimbus::media {

SplatFloor::SplatFloor() : program_(gpu::compileProgram({.vertex = "media/particles/splat_floor.vert", .fragment = "media/particles/splat_floor.frag"})) {}

void SplatFloor::draw(const ParticleGpuBuffer& buffer, GLuint framebuffer, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    gpu::applyPipeline(gpu::PipelineState::blending(gpu::kPremultipliedOver));  // as the media passes
    glUseProgram(program_.id());
    frameBlocks_.bind();
    buffer.bindParticles();
    glBindVertexArray(vertexArray_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
}

double SplatFloor::measure(const ParticleGpuBuffer& buffer, const gpu::View& view, int repeats) {
    if (buffer.count() == 0) return 0.0;
    HostFrame frame;
    frame.camera = view;
    frameBlocks_.pack(frame, {}, {});
    frameBlocks_.upload();
    const gpu::Texture target({GL_TEXTURE_2D, GL_RGBA32F, view.width, view.height, 1, 1});
    const gpu::Framebuffer framebuffer = gpu::createFramebuffer();
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    draw(buffer, framebuffer.id(), view.width, view.height);  // warm-up
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        draw(buffer, framebuffer.id(), view.width, view.height);
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return gpu::median(ms);
}

}  // namespace nimbus::media
