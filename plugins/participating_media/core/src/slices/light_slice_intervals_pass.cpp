// Light slices, last pass: one interval between planes to a layer, with its ends' neighbours
// (light_slice_intervals_pass.h), eight a draw. On llvmpipe each framebuffer change costs about as
// much as the copy it serves, so a draw takes as many intervals as eight draw buffers hold.
#include "slices/light_slice_intervals_pass.h"

#include <algorithm>

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
constexpr int kPlanesPerDraw = 8;  // light_slice_intervals.frag outIntervals
constexpr GLint kViewLayerLocation = 0;   // uViewLayer
constexpr GLint kFirstPlaneLocation = 1;  // uFirstPlane
constexpr GLint kPlanesLocation = 2;      // uPlanes
constexpr GLint kCropLocation = 3;        // uCrop
}  // namespace

LightSliceIntervalsPass::LightSliceIntervalsPass() : pass_("media/slices/light_slice_intervals.frag") {}

gpu::ResourceHandle LightSliceIntervalsPass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                             gpu::ResourceHandle packed) {
    int layers = 1;
    for (const SliceView& v : views) layers = std::max(layers, intervalLayer(v) + v.slices);
    struct Data {
        gpu::ResourceHandle packed, intervals;
    };
    const auto& data = graph.addPass<Data>(
        "light_slice_intervals",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.packed = builder.read(packed);
            d.intervals = builder.create("light_slice_intervals", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
        },
        [this, views, resolution](const gpu::PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glBindTextureUnit(kPackedSlicesUnit, resources.id(d.packed));
            for (const SliceView& v : views)
                for (int plane = 0; plane < v.slices; plane += kPlanesPerDraw) {
                    const int count = std::min(kPlanesPerDraw, v.slices - plane);
                    attachSliceLayers(fbo.id(), resources.id(d.intervals), intervalLayer(v) + plane, count);
                    glProgramUniform1i(pass_.program(), kViewLayerLocation, v.firstLayer);
                    glProgramUniform1i(pass_.program(), kFirstPlaneLocation, plane);
                    glProgramUniform1i(pass_.program(), kPlanesLocation, v.slices);
                    glProgramUniform1i(pass_.program(), kCropLocation, v.seedView >= 0 ? 1 : 0);
                    pass_.draw(fbo.id(), glm::ivec2(std::min(sliceTexels(v, resolution) + 1, resolution)));
                    detachSliceLayers(fbo.id(), count);
                }
        });
    return data.intervals;
}

}  // namespace nimbus::media
