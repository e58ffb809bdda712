#include "fill_rate_floor.h"

#include <chrono>
#include <vector>

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/pass_timer.h"

namespace nimbus::sandbox {

FillRateFloor::FillRateFloor(int width, int height)
    : width_(width), height_(height), target_({GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1}),
      framebuffer_(gpu::createFramebuffer()), vertexArray_(gpu::createVertexArray()) {
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, target_.id(), 0);
    program_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "bench/fill.frag"});
}

void FillRateFloor::draw(std::uint64_t fragments) {
    const auto screen = static_cast<std::uint64_t>(width_) * static_cast<std::uint64_t>(height_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // as the media passes
    glUseProgram(program_.id());
    glBindVertexArray(vertexArray_.id());
    for (std::uint64_t full = fragments / screen; full > 0; --full) glDrawArrays(GL_TRIANGLES, 0, 3);
    // The rest as whole rows (and one partial row) under a scissor.
    const std::uint64_t rest = fragments % screen;
    if (rest > 0) {
        glEnable(GL_SCISSOR_TEST);
        const auto rows = static_cast<GLsizei>(rest / static_cast<std::uint64_t>(width_));
        if (rows > 0) {
            glScissor(0, 0, width_, rows);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        const auto tail = static_cast<GLsizei>(rest % static_cast<std::uint64_t>(width_));
        if (tail > 0) {
            glScissor(0, rows, tail, 1);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glDisable(GL_SCISSOR_TEST);
    }
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

double FillRateFloor::measure(std::uint64_t fragments, int repeats) {
    draw(fragments);  // warm-up
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        draw(fragments);
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return render::median(ms);
}

}  // namespace nimbus::sandbox
