// Mixed resolution: the edges of a reduced media target within a rect of the viewport as stencil 1
// at full resolution, with the edge colour target initialised for the technique's redraw there
// (shaders/media/upsample/edge_stencil.frag).
#include "upsample/media_edge_stencil_pass.h"

#include "common/frame_blocks.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
constexpr GLint kScaleLocation = 1;      // edge_stencil.frag uScale
constexpr GLint kThresholdLocation = 2;  // edge_stencil.frag uThreshold
constexpr GLint kOffsetLocation = 3;     // edge_stencil.frag uOffset
constexpr GLint kWholeLocation = 4;      // edge_stencil.frag uWhole
// Every fragment the shader keeps (an edge) writes stencil 1 and its colour.
constexpr gpu::PipelineState kWriteStencil{
    .stencil = {.test = true, .compare = GL_ALWAYS, .reference = 1, .readMask = 0xFF, .writeMask = 0xFF, .pass = GL_REPLACE}};
}  // namespace

gpu::Framebuffer edgeFramebuffer(GLuint color, GLuint stencil) {
    gpu::Framebuffer fbo = gpu::createFramebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, color, 0);
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, stencil, 0);
    glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
    return fbo;
}

gpu::Framebuffer bindEdgeFramebuffer(GLuint color, GLuint stencil, glm::ivec4 rect, glm::ivec2 viewport) {
    gpu::Framebuffer fbo = edgeFramebuffer(color, stencil);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(-rect.x, -rect.y, viewport.x, viewport.y);
    return fbo;
}

gpu::PipelineState onEdges(gpu::PipelineState state) {
    state.stencil = {.test = true, .compare = GL_EQUAL, .reference = 1, .readMask = 0xFF, .writeMask = 0x00};
    return state;
}

MediaEdgeStencilPass::MediaEdgeStencilPass()
    : pass_("media/upsample/edge_stencil.frag"), clampedNearest_(gpu::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE)) {}

EdgeTarget MediaEdgeStencilPass::add(gpu::FrameGraph& graph, GraphFrame& context, gpu::ResourceHandle depthUsed, const MediaTarget& target,
                                     float threshold, glm::ivec4 rect, glm::ivec4 whole) {
    struct Data {
        gpu::ResourceHandle color, stencil, depthUsed, scene;
    };
    const glm::ivec2 full(context.host.camera.width, context.host.camera.height), size(rect.z, rect.w);
    // Textures in steps of 64 texels, so the pool reuses them while the rect moves with the camera.
    const glm::ivec2 allocated = (size + 63) / 64 * 64;
    const glm::vec2 scale = glm::vec2(target.size) / glm::vec2(full);
    const auto& data = graph.addPass<Data>(
        "media_edge_stencil",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.color = builder.create("media_edges", {GL_TEXTURE_2D, GL_RGBA32F, allocated.x, allocated.y, 1, 1});
            d.stencil = builder.create("media_edge_stencil", {GL_TEXTURE_2D, GL_DEPTH24_STENCIL8, allocated.x, allocated.y, 1, 1});
            d.depthUsed = builder.read(depthUsed);
            d.scene = builder.read(context.sceneDepth);
        },
        [this, &context, size, scale, threshold, rect, whole](const gpu::PassResources& r, const Data& d) {
            const gpu::Framebuffer fbo = edgeFramebuffer(r.id(d.color), r.id(d.stencil));
            gpu::applyPipeline(kWriteStencil);  // the clears write through its masks too
            const float notDrawn[4] = {0.0f, 0.0f, 0.0f, -1.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, notDrawn);
            glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
            context.blocks->bind();
            glProgramUniform2f(pass_.program(), kScaleLocation, scale.x, scale.y);
            glProgramUniform1f(pass_.program(), kThresholdLocation, threshold);
            glProgramUniform2f(pass_.program(), kOffsetLocation, static_cast<float>(rect.x), static_cast<float>(rect.y));
            glProgramUniform4f(pass_.program(), kWholeLocation, static_cast<float>(whole.x), static_cast<float>(whole.y),
                               static_cast<float>(whole.x + whole.z), static_cast<float>(whole.y + whole.w));
            glBindTextureUnit(kSceneDepthUnit, r.id(d.scene));
            glBindTextureUnit(kDepthUsedUnit, r.id(d.depthUsed));
            glBindSampler(kDepthUsedUnit, clampedNearest_.id());
            pass_.draw(fbo.id(), size, kWriteStencil);
            glBindSampler(kDepthUsedUnit, 0);
        });
    return {data.color, data.stencil, rect};
}

}  // namespace nimbus::media
