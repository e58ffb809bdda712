#include "nimbus/gpu/fullscreen_pass.h"

#include "nimbus/gpu/shader_program.h"

namespace nimbus::gpu {

FullscreenPass::FullscreenPass(const std::string& fragment, std::vector<std::string> defines)
    : program_(compileProgram({.vertex = "fullscreen.vert", .fragment = fragment, .defines = std::move(defines)})) {}

void FullscreenPass::draw(GLuint framebuffer, glm::ivec2 size, const PipelineState& state) const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, size.x, size.y);
    applyPipeline(state);
    glUseProgram(program_.id());
    glBindVertexArray(vertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

Framebuffer singleTargetFramebuffer(GLuint texture, GLenum format) {
    Framebuffer fbo = createFramebuffer();
    if (isDepthFormat(format)) {
        const bool stencil = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
        glNamedFramebufferTexture(fbo.id(), stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, texture, 0);
        glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
    } else {
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, texture, 0);
        glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
    }
    return fbo;
}

}  // namespace nimbus::gpu
