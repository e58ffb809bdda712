// Compose: the translucent layer (the media) and the fog blended over the opaque image, which the
// opaque pass drew into the persistent linear output, upsampling a reduced-resolution layer on the
// way, or taking the media's full-resolution edges where it drew them (shaders/compose.frag).
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
        if (variant & kEdges) defines.push_back("COMPOSE_EDGES");
        it = passes_.try_emplace(variant, "compose.frag", defines).first;
    }
    return it->second;
}

void ComposePass::add(FrameGraph& graph, FrameContext& context) {
    struct Data {
        ResourceHandle layer, depthUsed, edges, sceneDepth, output;
    };
    const TranslucentLayer overlay = context.overlay;
    const bool fog = context.input.environment.fog.mode != assets::FogMode::None;
    graph.addPass<Data>(
        "compose",
        [&](PassBuilder& builder, Data& d) {
            if (overlay.color.valid()) d.layer = builder.read(overlay.color);
            if (overlay.color.valid() && overlay.depthUsed.valid()) d.depthUsed = builder.read(overlay.depthUsed);
            if (d.depthUsed.valid() && overlay.edges.valid()) d.edges = builder.read(overlay.edges);
            if (d.depthUsed.valid() || fog) d.sceneDepth = builder.read(context.sceneDepth);
            d.output = builder.write(context.sceneColor);
            builder.sideEffect();
        },
        [this, &context, fog, threshold = overlay.edgeThreshold, rect = overlay.edgeRect](const PassResources& resources, const Data& d) {
            if (!d.layer.valid() && !fog) return;  // the opaque image is the frame
            const auto& desc = resources.desc(d.output);
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(resources.id(d.output), desc.format);
            const int variant = (d.layer.valid() ? kLayer : 0) | (d.depthUsed.valid() ? kUpsample : 0) | (fog ? kFog : 0);
            if (d.layer.valid()) glBindTextureUnit(1, resources.id(d.layer));
            if (d.sceneDepth.valid()) {
                context.frameData->bind();
                glBindTextureUnit(3, resources.id(d.sceneDepth));
            }
            if (d.depthUsed.valid()) {
                glBindTextureUnit(2, resources.id(d.depthUsed));
                glBindSampler(2, clampedNearest_.id());
            }
            if (d.edges.valid()) glBindTextureUnit(4, resources.id(d.edges));
            const glm::vec2 scale = d.layer.valid() ? glm::vec2(resources.desc(d.layer).width, resources.desc(d.layer).height) /
                                                          glm::vec2(desc.width, desc.height)
                                                    : glm::vec2(1.0f);
            const glm::ivec2 size(desc.width, desc.height);
            if (!d.edges.valid()) {
                draw(pass(variant), variant, fbo.id(), size, scale, threshold, rect);
            } else {
                // The edge variant's extra fetch only over the edge rect; the rest in strips around it.
                glEnable(GL_SCISSOR_TEST);
                const glm::ivec4 strips[4] = {{0, 0, size.x, rect.y},
                                              {0, rect.y + rect.w, size.x, size.y - rect.y - rect.w},
                                              {0, rect.y, rect.x, rect.w},
                                              {rect.x + rect.z, rect.y, size.x - rect.x - rect.z, rect.w}};
                for (const glm::ivec4& strip : strips)
                    if (strip.z > 0 && strip.w > 0) {
                        glScissor(strip.x, strip.y, strip.z, strip.w);
                        draw(pass(variant), variant, fbo.id(), size, scale, threshold, rect);
                    }
                glScissor(rect.x, rect.y, rect.z, rect.w);
                draw(pass(variant | kEdges), variant | kEdges, fbo.id(), size, scale, threshold, rect);
                glDisable(GL_SCISSOR_TEST);
            }
            glBindSampler(2, 0);
        });
}

// One draw of a compose variant: output = src.rgb + src.a · opaque; the opaque pass's alpha (1) stays.
void ComposePass::draw(const gpu::FullscreenPass& pass, int variant, GLuint framebuffer, glm::ivec2 size, glm::vec2 scale, float threshold,
                       glm::ivec4 edgeRect) {
    const GLuint program = pass.program();
    if (variant & kUpsample) {
        glProgramUniform2f(program, 1, scale.x, scale.y);
        glProgramUniform1f(program, 2, threshold);
    }
    if (variant & kEdges) glProgramUniform2i(program, 3, edgeRect.x, edgeRect.y);
    pass.draw(framebuffer, size,
              gpu::PipelineState::blending({.enabled = true, .srcRgb = GL_ONE, .dstRgb = GL_SRC_ALPHA, .srcAlpha = GL_ZERO, .dstAlpha = GL_ONE}));
}

}  // namespace nimbus::render
