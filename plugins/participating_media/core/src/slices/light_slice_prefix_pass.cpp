// Light slices in deposit form, second pass: per view, the running sum of its slabs written as the
// optical depth up to each slice plane, 4 slices per RGBA32F layer (shaders/media/slices/light_slice_prefix.frag).
#include <algorithm>

#include "slices/light_slice_prefix_pass.h"

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

LightSlicePrefixPass::LightSlicePrefixPass() : pass_("media/slices/light_slice_prefix.frag") {}

gpu::ResourceHandle LightSlicePrefixPass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                                 gpu::ResourceHandle slabs) {
    int layers = 0;
    for (const auto& v : views) layers = std::max(layers, v.firstLayer + (v.slices + 3) / 4);
    struct Data {
        gpu::ResourceHandle slabs, slices;
    };
    const auto& data = graph.addPass<Data>(
        "light_slice_prefix",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slabs = builder.read(slabs);
            d.slices = builder.create("light_slices", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
        },
        [this, views, resolution](const gpu::PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glBindTextureUnit(kSlabsUnit, resources.id(d.slabs));
            int firstSlab = 0;
            for (const SliceView& v : views) {
                bindSliceLayers(fbo.id(), resources.id(d.slices), v);
                glProgramUniform1i(pass_.program(), 0, firstSlab);
                glProgramUniform1i(pass_.program(), 1, v.slices);
                pass_.draw(fbo.id(), glm::ivec2(resolution));
                unbindSliceLayers(fbo.id(), v);
                firstSlab += v.slices;
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
