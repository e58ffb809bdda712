#include "frame/host_depth_pass.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
inline constexpr GLint kPlanesLocation = 0;    // host_depth.frag uPlanes
inline constexpr GLint kReversedLocation = 1;  // host_depth.frag uReversed
}  // namespace

HostDepthPass::HostDepthPass() { program_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/frame/host_depth.frag"}); }

gpu::ResourceHandle HostDepthPass::add(gpu::FrameGraph& graph, gpu::ResourceHandle hostDepth, const gpu::View& camera) {
    struct Data {
        gpu::ResourceHandle host, depth;
    };
    const auto& data = graph.addPass<Data>(
        "media_host_depth",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.host = builder.read(hostDepth);
            d.depth = builder.create("media_scene_depth", {GL_TEXTURE_2D, GL_R32F, camera.width, camera.height, 1, 1});
        },
        [this, camera](const gpu::PassResources& r, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.depth), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, camera.width, camera.height);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
            const GLuint program = program_.id();
            glUseProgram(program);
            glProgramUniform3f(program, kPlanesLocation, camera.znear, camera.zfar, camera.orthographic ? 1.0f : 0.0f);
            const glm::vec2 ab = camera.depthLinearization();
            glProgramUniform2f(program, kReversedLocation, ab.x, ab.y);
            glBindTextureUnit(kHostDepthUnit, r.id(d.host));
            glBindVertexArray(vertexArray_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.depth;
}

}  // namespace nimbus::media
