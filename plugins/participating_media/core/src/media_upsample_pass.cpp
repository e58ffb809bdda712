// Offscreen media (seed 002): the media pass runs at ½ or ¼ resolution; this records the depth each
// reduced texel used and upsamples with depth awareness (shaders/media/depth_used.frag, upsample.frag).
#include "media_passes.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"

namespace nimbus::media {

MediaUpsamplePass::MediaUpsamplePass() {
    depthProgram_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/depth_used.frag"});
    upsampleProgram_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/upsample.frag"});
}

render::ResourceHandle MediaUpsamplePass::add(render::FrameGraph& graph, render::FrameContext& context, render::ResourceHandle low,
                                              const MediaTarget& target, float threshold) {
    struct DepthUsed {
        render::ResourceHandle depth, scene;
    };
    const glm::ivec2 lowSize = target.size;
    const auto& used = graph.addPass<DepthUsed>(
        "media_depth_used",
        [&](render::PassBuilder& builder, DepthUsed& d) {
            d.depth = builder.create("media_depth_used", {GL_TEXTURE_2D, GL_R32F, lowSize.x, lowSize.y, 1, 1});
            d.scene = builder.read(context.sceneDepth);
        },
        [this, &context, lowSize, scale = target.fullResScale](const render::PassResources& r, const DepthUsed& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.depth), 0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, lowSize.x, lowSize.y);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glUseProgram(depthProgram_.id());
            context.frameData->bind();
            glProgramUniform2f(depthProgram_.id(), 1, scale.x, scale.y);
            glBindTextureUnit(render::kSceneDepthUnit, r.id(d.scene));
            glBindVertexArray(vertexArray_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });

    struct Upsample {
        render::ResourceHandle media, low, depthLow, scene;
    };
    const int w = context.view.width, h = context.view.height;
    const auto& data = graph.addPass<Upsample>(
        "media_upsample",
        [&](render::PassBuilder& builder, Upsample& d) {
            d.media = builder.create("media_color", {GL_TEXTURE_2D, GL_RGBA32F, w, h, 1, 1});
            d.low = builder.read(low);
            d.depthLow = builder.read(used.depth);
            d.scene = builder.read(context.sceneDepth);
        },
        [this, &context, w, h, lowSize, threshold](const render::PassResources& r, const Upsample& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.media), 0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, w, h);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            const GLuint program = upsampleProgram_.id();
            glUseProgram(program);
            context.frameData->bind();
            glProgramUniform2f(program, 0, static_cast<float>(lowSize.x) / static_cast<float>(w),
                               static_cast<float>(lowSize.y) / static_cast<float>(h));
            glProgramUniform1f(program, 1, threshold);
            glBindTextureUnit(0, r.id(d.low));
            glBindTextureUnit(1, r.id(d.depthLow));
            glBindTextureUnit(render::kSceneDepthUnit, r.id(d.scene));
            glBindVertexArray(vertexArray_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.media;
}

}  // namespace nimbus::media
