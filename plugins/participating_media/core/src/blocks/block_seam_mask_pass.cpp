// Blocks mode: the seam mask (shaders/media/blocks/block_seam.glsl) — where the opaque surface lies among
// the particles of a block a mesh comes near, one texel per kSeamMaskCell² media texels.
#include "blocks/block_seam_mask_pass.h"

#include <algorithm>

#include "common/frame_blocks.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

namespace {
inline constexpr GLint kFullResScaleLocation = 1;  // block_seam_mask.frag
inline constexpr GLint kFirstRankLocation = 2;     // block_composite.vert
inline constexpr GLint kMediaSizeLocation = 3;     // block_seam_mask.frag
inline constexpr GLint kRectWideningLocation = 4;  // block_composite.vert
inline constexpr GLint kCellLocation = 5;          // block_seam_mask.frag
}  // namespace

int seamMaskCell(glm::ivec2 size) { return std::max(4, (std::min(size.x, size.y) + 47) / 48); }

BlockSeamMaskPass::BlockSeamMaskPass() {
    program_ = gpu::compileProgram({.vertex = "media/blocks/block_composite.vert", .fragment = "media/blocks/block_seam_mask.frag"});
}

gpu::ResourceHandle BlockSeamMaskPass::add(gpu::FrameGraph& graph, GraphFrame& context, std::vector<BlockRankRun> runs,
                                                 const BlockGpuBuffers& blocks, gpu::ResourceHandle impostorDepths,
                                                 const MediaTarget& target, int cell) {
    struct Mask {
        gpu::ResourceHandle mask, depth, impostorDepths;
    };
    const glm::ivec2 cells = (target.size + (cell - 1)) / cell;
    const auto& data = graph.addPass<Mask>(
        "block_seam_mask",
        [&](gpu::PassBuilder& builder, Mask& d) {
            d.mask = builder.create("block_seam_mask", {GL_TEXTURE_2D, GL_R8, cells.x, cells.y, 1, 1});
            d.depth = builder.read(context.sceneDepth);
            d.impostorDepths = builder.read(impostorDepths);
        },
        [this, runs = std::move(runs), &context, &blocks, target, cell](const gpu::PassResources& r, const Mask& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.mask), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
            // The blocks' NDC rectangles are the media target's: a viewport of size/cell cells puts
            // mask cell i over media texels [i·cell, (i + 1)·cell). Each rectangle is widened by one
            // cell, so every cell it touches gets a fragment.
            const glm::vec2 viewport = glm::vec2(target.size) / static_cast<float>(cell);
            glViewportIndexedf(0, 0.0f, 0.0f, viewport.x, viewport.y);
            const GLuint program = program_.id();
            glUseProgram(program);
            glProgramUniform2f(program, kFullResScaleLocation, target.fullResScale.x, target.fullResScale.y);
            glProgramUniform2i(program, kMediaSizeLocation, target.size.x, target.size.y);
            glProgramUniform1i(program, kCellLocation, cell);
            glProgramUniform2f(program, kRectWideningLocation, 2.0f / viewport.x, 2.0f / viewport.y);
            context.blocks->bind();
            blocks.bind(0);
            glBindTextureUnit(kSceneDepthUnit, r.id(d.depth));
            glBindTextureUnit(kImpostorDepthsUnit, r.id(d.impostorDepths));
            gpu::applyPipeline({});  // every fragment writes 1
            glBindVertexArray(vertexArray_.id());
            for (const BlockRankRun& run : runs) {
                glProgramUniform1i(program, kFirstRankLocation, run.first);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, run.count);
            }
        });
    return data.mask;
}

}  // namespace nimbus::media
