// Depth impostors of blocks (Umenhoffer and Szirmay-Kalos §2.1): every particle drawn once into its block's atlas tile,
// blending MIN for the front/back depths and ADD for optical depth in the same pass.
#include "blocks/block_impostor_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {
namespace {

// The paper's min for the depths with a separate alpha equation (add, the optical depth) on target
// 0; the sums and moments add; the tile's rectangle is four clip planes.
constexpr gpu::PipelineState impostorState() {
    gpu::PipelineState state = gpu::PipelineState::blending(gpu::kAdditive);
    state.blend[0].equationRgb = GL_MIN;
    state.clipDistances = 4;
    return state;
}

}  // namespace

BlockImpostorRenderer::BlockImpostorRenderer() {
    program_ = gpu::compileProgram({.vertex = "media/blocks/block_impostors.vert", .fragment = "media/blocks/block_impostors.frag"});
}

void BlockImpostorRenderer::render(const BlockViewPlan& plan, std::size_t tileSet, const ImpostorTargets& targets,
                                   const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles) const {
    gpu::Framebuffer fbo = gpu::createFramebuffer();
    const GLuint textures[4] = {targets.depths, targets.sums1, targets.sums2, targets.moments};
    GLenum drawBuffers[4];
    for (GLuint i = 0; i < 4; ++i) {
        if (textures[i] != 0) glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0 + i, textures[i], 0);
        drawBuffers[i] = textures[i] != 0 ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
    }
    glNamedFramebufferDrawBuffers(fbo.id(), 4, drawBuffers);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    // Front and −back start at +∞ for MIN; optical depth and the sums start at 0.
    const float far[4] = {3.0e38f, 3.0e38f, 3.0e38f, 0.0f}, zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, far);
    for (GLint i = 1; i < 4; ++i)
        if (textures[i] != 0) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, zero);
    glViewport(0, 0, plan.atlasSize.x, plan.atlasSize.y);
    gpu::applyPipeline(impostorState());

    const GLuint program = program_.id();
    glUseProgram(program);
    particles.bindParticles();
    blocks.bind(tileSet);
    const glm::mat4 projection = plan.view.viewProjection * glm::inverse(plan.view.view);
    // Views are symmetric: their half extent is the projection's scale (media/common/view_rays.glsl).
    const glm::vec2 halfExtent(1.0f / projection[0][0], 1.0f / projection[1][1]);
    const glm::vec4 params(plan.view.perspective ? 1.0f : 0.0f, plan.view.nearDepth, 0.0f, 0.0f);
    const glm::vec2 atlas(plan.atlasSize);
    glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, glm::value_ptr(plan.view.view));
    glProgramUniformMatrix4fv(program, 1, 1, GL_FALSE, glm::value_ptr(projection));
    glProgramUniform4fv(program, 2, 1, glm::value_ptr(params));
    glProgramUniform2fv(program, 3, 1, glm::value_ptr(atlas));
    glProgramUniform2fv(program, 4, 1, glm::value_ptr(halfExtent));
    glProgramUniform3fv(program, 5, 1, glm::value_ptr(plan.view.eye));
    glBindVertexArray(vertexArray_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(blocks.itemCount()));
}

}  // namespace nimbus::media
