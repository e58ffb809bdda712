// Blocks mode: the texels the seam weight reaches (shaders/media/blocks/block_seam_stencil.frag), as
// stencil 1 at the media target's size, so the composite's two draws of a seam run skip the rest
// before shading rather than reading the mask and discarding (docs/design-notes.md).
#include "blocks/block_seam_stencil_pass.h"

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
inline constexpr GLint kCellLocation = 5;  // block_seam_stencil.frag
// Every fragment the mask keeps writes stencil 1.
constexpr gpu::PipelineState kWriteStencil{
    .stencil = {.test = true, .compare = GL_ALWAYS, .reference = 1, .readMask = 0xFF, .writeMask = 0xFF, .pass = GL_REPLACE}};

}  // namespace

BlockSeamStencilPass::BlockSeamStencilPass() : pass_("media/blocks/block_seam_stencil.frag") {}

gpu::ResourceHandle BlockSeamStencilPass::add(gpu::FrameGraph& graph, gpu::ResourceHandle mask, const MediaTarget& target, int cell) {
    struct Stencil {
        gpu::ResourceHandle mask, stencil;
    };
    const auto& data = graph.addPass<Stencil>(
        "block_seam_stencil",
        [&](gpu::PassBuilder& builder, Stencil& d) {
            d.mask = builder.read(mask);
            d.stencil = builder.create("block_seam_stencil", {GL_TEXTURE_2D, GL_DEPTH24_STENCIL8, target.size.x, target.size.y, 1, 1});
        },
        [this, target, cell](const gpu::PassResources& r, const Stencil& d) {
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.stencil), GL_DEPTH24_STENCIL8);
            gpu::applyPipeline(kWriteStencil);  // the clear writes through its masks too
            glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
            glProgramUniform1i(pass_.program(), kCellLocation, cell);
            glBindTextureUnit(kSeamMaskUnit, r.id(d.mask));
            pass_.draw(fbo.id(), target.size, kWriteStencil);
        });
    return data.stencil;
}

}  // namespace nimbus::media
