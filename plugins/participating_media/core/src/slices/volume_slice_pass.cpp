#include "slices/volume_slice_pass.h"

namespace nimbus::media {

VolumeSlicePass::VolumeSlicePass() : pass_("media/slices/volume_slices.frag") {}

gpu::ResourceHandle VolumeSlicePass::add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views,
                                         int resolution, const VolumeGpuBuffer& volumes) {
    struct Data {
        gpu::ResourceHandle slices;
    };
    const auto& data = graph.addPass<Data>(
        "volume_slices", [&](gpu::PassBuilder& builder, Data& d) { d.slices = builder.write(slices); },
        [this, views, resolution, &volumes](const gpu::PassResources& resources, const Data& d) {
            const gpu::Framebuffer fbo = gpu::createFramebuffer();
            const GLuint program = pass_.program();
            volumes.bind();
            glProgramUniform1i(program, 7, volumes.count());
            for (const SliceView& v : views) {
                bindSliceLayers(fbo.id(), resources.id(d.slices), v, false);
                setSliceViewUniforms(program, v, resolution);
                // FullscreenPass::draw binds the framebuffer again with the same attachments.
                pass_.draw(fbo.id(), {resolution, resolution}, kSliceAdd);
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
