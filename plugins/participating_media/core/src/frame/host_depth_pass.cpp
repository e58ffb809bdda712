#include "frame/host_depth_pass.h"

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
inline constexpr GLint kPlanesLocation = 0;    // host_depth.frag uPlanes
inline constexpr GLint kReversedLocation = 1;  // host_depth.frag uReversed
}  // namespace

HostDepthPass::HostDepthPass() : pass_("media/frame/host_depth.frag") {}

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
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.depth), GL_R32F);
            const GLuint program = pass_.program();
            glProgramUniform3f(program, kPlanesLocation, camera.znear, camera.zfar, camera.orthographic ? 1.0f : 0.0f);
            const glm::vec2 ab = camera.depthLinearization();
            glProgramUniform2f(program, kReversedLocation, ab.x, ab.y);
            glBindTextureUnit(kHostDepthUnit, r.id(d.host));
            pass_.draw(fbo.id(), {camera.width, camera.height});
        });
    return data.depth;
}

}  // namespace nimbus::media
