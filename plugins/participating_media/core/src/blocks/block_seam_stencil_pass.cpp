// Blocks mode: the texels the seam weight reaches (shaders/media/blocks/block_seam_stencil.frag), as
// stencil 1 at the media target's size, so the composite's two draws of a seam run skip the rest
// before shading rather than reading the mask and discarding (docs/design-notes.md).
#include "blocks/block_seam_stencil_pass.h"

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

namespace {
inline constexpr GLint kCellLocation = 5;  // block_seam_stencil.frag
}  // namespace

BlockSeamStencilPass::BlockSeamStencilPass() {
    program_ = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/blocks/block_seam_stencil.frag"});
}

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
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, r.id(d.stencil), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(target.size.x), static_cast<float>(target.size.y));
            glStencilMask(0xFF);  // the clear writes through it too
            glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
            glUseProgram(program_.id());
            glProgramUniform1i(program_.id(), kCellLocation, cell);
            glBindTextureUnit(kSeamMaskUnit, r.id(d.mask));
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_CULL_FACE);
            glDisable(GL_BLEND);
            glEnable(GL_STENCIL_TEST);
            glStencilFunc(GL_ALWAYS, 1, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            glBindVertexArray(vertexArray_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glDisable(GL_STENCIL_TEST);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.stencil;
}

}  // namespace nimbus::media
