// Light slices, last pass: two planes to a layer beside their predecessors (light_slice_pairs_pass.h),
// sixteen planes a draw. On llvmpipe each framebuffer change costs about as much as the copy it
// serves, so a draw takes as many planes as eight draw buffers hold.
#include "slices/light_slice_pairs_pass.h"

#include <algorithm>

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
constexpr int kLayersPerDraw = 8;                    // light_slice_pairs.frag outPairs
constexpr int kPlanesPerDraw = 2 * kLayersPerDraw;
constexpr GLint kFirstLayerLocation = 0;             // uFirstLayer
constexpr GLint kFirstPlaneLocation = 1;             // uFirstPlane
}  // namespace

LightSlicePairsPass::LightSlicePairsPass() : pass_("media/slices/light_slice_pairs.frag") {}

gpu::ResourceHandle LightSlicePairsPass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                             gpu::ResourceHandle packed) {
    int layers = 1;
    for (const SliceView& v : views) layers = std::max(layers, 2 * v.firstLayer + (v.slices + 1) / 2);
    struct Data {
        gpu::ResourceHandle packed, pairs;
    };
    const auto& data = graph.addPass<Data>(
        "light_slice_pairs",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.packed = builder.read(packed);
            d.pairs = builder.create("light_slice_pairs", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
        },
        [this, views, resolution](const gpu::PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glBindTextureUnit(kPackedSlicesUnit, resources.id(d.packed));
            for (const SliceView& v : views)
                for (int plane = 0; plane < v.slices; plane += kPlanesPerDraw) {
                    const int count = (std::min(kPlanesPerDraw, v.slices - plane) + 1) / 2;
                    attachSliceLayers(fbo.id(), resources.id(d.pairs), 2 * v.firstLayer + plane / 2, count);
                    glProgramUniform1i(pass_.program(), kFirstLayerLocation, v.firstLayer + plane / 4);
                    glProgramUniform1i(pass_.program(), kFirstPlaneLocation, plane);
                    pass_.draw(fbo.id(), glm::ivec2(resolution));
                    detachSliceLayers(fbo.id(), count);
                }
        });
    return data.pairs;
}

}  // namespace nimbus::media
