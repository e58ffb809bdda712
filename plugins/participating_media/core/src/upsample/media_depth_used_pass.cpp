// Offscreen media (Jendersie's offscreen particles): the media pass runs at ½ or ¼ resolution; this records the
// view depth each reduced texel used (shaders/media/upsample/depth_used.frag), which the compose pass needs to
// upsample the media target with depth awareness (shaders/common/upsample.glsl), over the medium's cover.
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
    // Only the texels a composed pixel reads: those under the medium's cover, and one more each way.
    glm::ivec4 texels(0, 0, size);
    if (target.cover.z > 0) {
        const glm::ivec2 lo = glm::max(glm::ivec2(glm::floor(glm::vec2(target.cover.x, target.cover.y) / target.fullResScale)) - 1, glm::ivec2(0));
        const glm::ivec2 hi = glm::min(
            glm::ivec2(glm::ceil(glm::vec2(target.cover.x + target.cover.z, target.cover.y + target.cover.w) / target.fullResScale)) + 1, size);
        texels = glm::ivec4(lo, hi - lo);
    }
    const auto& data = graph.addPass<Data>(
        "media_depth_used",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.depth = builder.create("media_depth_used", {GL_TEXTURE_2D, GL_R32F, size.x, size.y, 1, 1});
            d.scene = builder.read(context.sceneDepth);
        },
        [this, &context, size, texels, scale = target.fullResScale](const gpu::PassResources& r, const Data& d) {
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.depth), GL_R32F);
            context.blocks->bind();
            glProgramUniform2f(pass_.program(), 1, scale.x, scale.y);
            glBindTextureUnit(kSceneDepthUnit, r.id(d.scene));
            // The rest holds 0, finite: a host that upsamples the empty layer there (with fog) gets
            // it back whatever the weights (common/upsample.glsl).
            if (texels != glm::ivec4(0, 0, size)) {
                const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
                glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
            }
            glEnable(GL_SCISSOR_TEST);
            glScissor(texels.x, texels.y, texels.z, texels.w);
            pass_.draw(fbo.id(), size);
            glDisable(GL_SCISSOR_TEST);
        });
    return data.depth;
}

}  // namespace nimbus::media
