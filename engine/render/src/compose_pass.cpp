// Compose: the translucent layer (the media) over opaque into the persistent linear output,
// upsampling a reduced-resolution layer on the way (shaders/compose.frag).
#include "passes.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"

namespace nimbus::render {

ComposePass::ComposePass() : clampedNearest_(gpu::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE)) {}

GLuint ComposePass::program(int variant) {
    auto it = programs_.find(variant);
    if (it == programs_.end()) {
        std::vector<std::string> defines;
        if (variant & kLayer) defines.push_back("COMPOSE_LAYER");
        if (variant & kUpsample) defines.push_back("COMPOSE_UPSAMPLE");
        if (variant & kFog) defines.push_back("COMPOSE_FOG");
        it = programs_.emplace(variant, gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "compose.frag", .defines = defines}))
                 .first;
    }
    return it->second.id();
}

void ComposePass::add(FrameGraph& graph, FrameContext& context, const gpu::Texture& output) {
    struct Data {
        ResourceHandle color, layer, depthUsed, sceneDepth, output;
    };
    const TranslucentLayer overlay = context.overlay;
    const bool fog = context.input.environment.fog.mode != assets::FogMode::None;
    graph.addPass<Data>(
        "compose",
        [&](PassBuilder& builder, Data& d) {
            d.color = builder.read(context.sceneColor);
            if (overlay.color.valid()) d.layer = builder.read(overlay.color);
            if (overlay.color.valid() && overlay.depthUsed.valid()) d.depthUsed = builder.read(overlay.depthUsed);
            if (d.depthUsed.valid() || fog) d.sceneDepth = builder.read(context.sceneDepth);
            d.output = builder.write(graph.importTexture("output", output));
            builder.sideEffect();
        },
        [this, &context, fog, threshold = overlay.edgeThreshold](const PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            const auto& desc = resources.desc(d.output);
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, resources.id(d.output), 0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, desc.width, desc.height);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glDisable(GL_CULL_FACE);
            const bool upsample = d.depthUsed.valid();
            const GLuint program = this->program((d.layer.valid() ? kLayer : 0) | (upsample ? kUpsample : 0) | (fog ? kFog : 0));
            glUseProgram(program);
            glBindTextureUnit(0, resources.id(d.color));
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
            triangle_.draw();
            glBindSampler(2, 0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
}

}  // namespace nimbus::render
