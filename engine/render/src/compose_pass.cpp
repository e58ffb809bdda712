// Compose: the translucent layer (the media) and the fog blended over the opaque image, which the
// opaque pass drew into the persistent linear output, upsampling a reduced-resolution layer on the
// way (shaders/compose.frag).
#include "passes.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"

namespace nimbus::render {

ComposePass::ComposePass() : clampedNearest_(gpu::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE)) {}

const gpu::FullscreenPass& ComposePass::pass(int variant) {
    auto it = passes_.find(variant);
    if (it == passes_.end()) {
        std::vector<std::string> defines;
        if (variant & kLayer) defines.push_back("COMPOSE_LAYER");
        if (variant & kUpsample) defines.push_back("COMPOSE_UPSAMPLE");
        if (variant & kFog) defines.push_back("COMPOSE_FOG");
        it = passes_.try_emplace(variant, "compose.frag", defines).first;
    }
    return it->second;
}

void ComposePass::add(FrameGraph& graph, FrameContext& context) {
    struct Data {
        ResourceHandle layer, depthUsed, sceneDepth, output;
    };
    const TranslucentLayer overlay = context.overlay;
    const bool fog = context.input.environment.fog.mode != assets::FogMode::None;
    graph.addPass<Data>(
        "compose",
        [&](PassBuilder& builder, Data& d) {
            if (overlay.color.valid()) d.layer = builder.read(overlay.color);
            if (overlay.color.valid() && overlay.depthUsed.valid()) d.depthUsed = builder.read(overlay.depthUsed);
            if (d.depthUsed.valid() || fog) d.sceneDepth = builder.read(context.sceneDepth);
            d.output = builder.write(context.sceneColor);
            builder.sideEffect();
        },
        [this, &context, fog, threshold = overlay.edgeThreshold](const PassResources& resources, const Data& d) {
            if (!d.layer.valid() && !fog) return;  // the opaque image is the frame
            const auto& desc = resources.desc(d.output);
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(resources.id(d.output), desc.format);
            const bool upsample = d.depthUsed.valid();
            const gpu::FullscreenPass& pass = this->pass((d.layer.valid() ? kLayer : 0) | (upsample ? kUpsample : 0) | (fog ? kFog : 0));
            const GLuint program = pass.program();
            if (d.layer.valid()) glBindTextureUnit(1, resources.id(d.layer));
            if (d.sceneDepth.valid()) {
                context.frameData->bind();
                glBindTextureUnit(3, resources.id(d.sceneDepth));
            }
            if (upsample) {
                const auto& low = resources.desc(d.layer);
                glBindTextureUnit(2, resources.id(d.depthUsed));
                glBindSampler(2, clampedNearest_.id());
                glProgramUniform2f(program, 1, static_cast<float>(low.width) / static_cast<float>(desc.width),
                                   static_cast<float>(low.height) / static_cast<float>(desc.height));
                glProgramUniform1f(program, 2, threshold);
            }
            // output = src.rgb + src.a · opaque; the opaque pass's alpha (1) stays.
            pass.draw(fbo.id(), {desc.width, desc.height},
                      gpu::PipelineState::blending({.enabled = true, .srcRgb = GL_ONE, .dstRgb = GL_SRC_ALPHA, .srcAlpha = GL_ZERO, .dstAlpha = GL_ONE}));
            glBindSampler(2, 0);
        });
}

}  // namespace nimbus::render
