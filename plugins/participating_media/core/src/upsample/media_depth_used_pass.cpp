// Offscreen media (Jendersie's offscreen particles): the media pass runs at ½ or ¼ resolution; this records the
// view depth each reduced texel used (shaders/media/upsample/depth_used.frag), which the compose pass needs to
// upsample the media target with depth awareness (shaders/common/upsample.glsl).
#include "upsample/media_depth_used_pass.h"

#include "common/frame_blocks.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

MediaDepthUsedPass::MediaDepthUsedPass() : pass_("media/upsample/depth_used.frag") {}

gpu::ResourceHandle MediaDepthUsedPass::add(gpu::FrameGraph& graph, GraphFrame& context, const MediaTarget& target) {
    struct Data {
        gpu::ResourceHandle depth, scene;
    };
    const glm::ivec2 size = target.size;
    const auto& data = graph.addPass<Data>(
        "media_depth_used",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.depth = builder.create("media_depth_used", {GL_TEXTURE_2D, GL_R32F, size.x, size.y, 1, 1});
            d.scene = builder.read(context.sceneDepth);
        },
        [this, &context, size, scale = target.fullResScale](const gpu::PassResources& r, const Data& d) {
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.depth), GL_R32F);
            context.blocks->bind();
            glProgramUniform2f(pass_.program(), 1, scale.x, scale.y);
            glBindTextureUnit(kSceneDepthUnit, r.id(d.scene));
            pass_.draw(fbo.id(), size);
        });
    return data.depth;
}

}  // namespace nimbus::media
