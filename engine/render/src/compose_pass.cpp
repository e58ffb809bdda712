// Compose: the translucent layer (the media) and the fog blended over the opaque image, which the
// opaque pass drew into the persistent linear output, upsampling a reduced-resolution layer on the
// way, or taking the media's full-resolution edges where it drew them (shaders/compose.frag).
#include "passes.h"

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"

namespace nimbus::render {

namespace {
glm::ivec4 intersect(glm::ivec4 a, glm::ivec4 b) {
    const glm::ivec2 lo = glm::max(glm::ivec2(a), glm::ivec2(b)), hi = glm::min(glm::ivec2(a) + glm::ivec2(a.z, a.w), glm::ivec2(b) + glm::ivec2(b.z, b.w));
    return hi.x > lo.x && hi.y > lo.y ? glm::ivec4(lo, hi - lo) : glm::ivec4(0);
}
}  // namespace

std::vector<std::pair<glm::ivec4, bool>> composeRects(glm::ivec2 size, glm::ivec4 composed, glm::ivec4 edgeRect) {
    std::vector<std::pair<glm::ivec4, bool>> rects;
    const auto add = [&](glm::ivec4 r, bool edges) {
        if (const glm::ivec4 own = intersect(r, composed); own.z > 0) rects.emplace_back(own, edges);
    };
    if (edgeRect.z <= 0) {
        add({0, 0, size.x, size.y}, false);
        return rects;
    }
    const glm::ivec4 e = edgeRect;
    add({0, 0, size.x, e.y}, false);
    add({0, e.y + e.w, size.x, size.y - e.y - e.w}, false);
    add({0, e.y, e.x, e.w}, false);
    add({e.x + e.z, e.y, size.x - e.x - e.z, e.w}, false);
    add(e, true);
    return rects;
}

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
        [this, &context, fog, threshold = overlay.edgeThreshold, rect = overlay.edgeRect, cover = overlay.coverRect](
            const PassResources& resources, const Data& d) {
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
            // Without fog the pixels outside the layer's cover are the opaque image already.
            const glm::ivec4 composed = !fog && cover.z > 0 ? cover : glm::ivec4(0, 0, size);
            glEnable(GL_SCISSOR_TEST);
            for (const auto& [strip, edges] : composeRects(size, composed, d.edges.valid() ? rect : glm::ivec4(0))) {
                glScissor(strip.x, strip.y, strip.z, strip.w);
                // The edge variant's extra fetch only over the edge rect.
                draw(pass(variant | (edges ? kEdges : 0)), variant | (edges ? kEdges : 0), fbo.id(), size, scale, threshold, rect);
            }
            glDisable(GL_SCISSOR_TEST);
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
