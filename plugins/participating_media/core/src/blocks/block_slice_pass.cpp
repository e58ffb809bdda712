// Blocks mode, light side (Umenhoffer and Szirmay-Kalos §2.2): in each light view, every block spread over the slices
// by its depth profile from the view's light impostors (block_slices.frag).
#include <glm/gtc/type_ptr.hpp>

#include "blocks/block_slice_pass.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

BlockSlicePass::BlockSlicePass() {
    program_ = gpu::compileProgram({.vertex = "media/blocks/block_slices.vert", .fragment = "media/blocks/block_slices.frag"});
}

gpu::TextureDesc BlockSlicePass::sliceDesc(const std::vector<SliceView>& views, int resolution) {
    int layers = 0;
    for (const SliceView& v : views) layers = std::max(layers, v.firstLayer + (v.slices + 3) / 4);
    return {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1};
}

gpu::ResourceHandle BlockSlicePass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views,
                                        const std::vector<BlockViewPlan>& plans, const BlockLightImpostors& impostors,
                                        const gpu::TextureDesc& desc, const BlockGpuBuffers& blocks, const gpu::Texture* keep) {
    const int resolution = desc.width;
    const gpu::ResourceHandle kept = keep != nullptr ? graph.importTexture("light_slices", *keep) : gpu::ResourceHandle{};
    struct Data {
        gpu::ResourceHandle slices;
        std::vector<gpu::ResourceHandle> impostors, moments;
    };
    const auto& data = graph.addPass<Data>(
        "block_light_slices",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slices = kept.valid() ? builder.write(kept) : builder.create("light_slices", desc);
            for (gpu::ResourceHandle h : impostors.depths) d.impostors.push_back(builder.read(h));
            for (gpu::ResourceHandle h : impostors.moments) d.moments.push_back(builder.read(h));
        },
        [this, views, &plans, resolution, &blocks](const gpu::PassResources& r, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            const GLuint program = program_.id();
            for (std::size_t i = 0; i < views.size(); ++i) {
                const SliceView& v = views[i];
                const int texels = sliceTexels(v, resolution);
                bindSliceLayers(fbo.id(), r.id(d.slices), v);
                setAdditiveSliceState(texels);
                glUseProgram(program);
                blocks.bind(i + 1);
                glBindTextureUnit(kImpostorDepthsUnit, r.id(d.impostors[i]));
                glBindTextureUnit(kSliceImpostorMomentsUnit, r.id(d.moments[i]));
                setSliceViewUniforms(program, v, texels);
                glBindVertexArray(vertexArray_.id());
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(plans[i].tiles.size()));
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
