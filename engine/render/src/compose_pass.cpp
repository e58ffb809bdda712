// Compose: medium over opaque into the persistent linear output (shaders/compose.frag).
#include "passes.h"

#include "nimbus/gpu/shader_program.h"

namespace nimbus::render {

ComposePass::ComposePass() { program_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "compose.frag"}); }

void ComposePass::add(FrameGraph& graph, FrameContext& context, const gpu::Texture& output) {
    struct Data {
        ResourceHandle color, media, output;
    };
    graph.addPass<Data>(
        "compose",
        [&](PassBuilder& builder, Data& d) {
            d.color = builder.read(context.sceneColor);
            if (context.mediaColor.valid()) d.media = builder.read(context.mediaColor);
            d.output = builder.write(graph.importTexture("output", output));
            builder.sideEffect();
        },
        [this](const PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            const auto& desc = resources.desc(d.output);
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, resources.id(d.output), 0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, desc.width, desc.height);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glDisable(GL_CULL_FACE);
            glUseProgram(program_.id());
            glBindTextureUnit(0, resources.id(d.color));
            glProgramUniform1i(program_.id(), 0, d.media.valid() ? 1 : 0);
            if (d.media.valid()) glBindTextureUnit(1, resources.id(d.media));
            triangle_.draw();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
}

}  // namespace nimbus::render
