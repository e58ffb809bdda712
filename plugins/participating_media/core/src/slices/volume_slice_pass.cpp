#include "slices/volume_slice_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

VolumeSlicePass::VolumeSlicePass() : pass_("media/slices/volume_slices.frag") {}

gpu::ResourceHandle VolumeSlicePass::add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views,
                                         int resolution, const VolumeGpuBuffer& volumes, const NoiseGridInput* noise) {
    if (noise != nullptr && !noisePass_) noisePass_ = std::make_unique<gpu::FullscreenPass>("media/slices/volume_slices.frag", std::vector<std::string>{"VOLUME_NOISE_GRID"});
    const gpu::FullscreenPass& pass = noise != nullptr ? *noisePass_ : pass_;
    const NoiseGridInput grid = noise != nullptr ? *noise : NoiseGridInput{};
    struct Data {
        gpu::ResourceHandle slices;
    };
    const auto& data = graph.addPass<Data>(
        "volume_slices", [&](gpu::PassBuilder& builder, Data& d) { d.slices = builder.write(slices); },
        [&pass, views, resolution, &volumes, grid](const gpu::PassResources& resources, const Data& d) {
            const gpu::Framebuffer fbo = gpu::createFramebuffer();
            const GLuint program = pass.program();
            volumes.bind();
            glProgramUniform1i(program, 7, volumes.count());
            if (grid.texture != nullptr) {
                glBindTextureUnit(kNoiseGridUnit, grid.texture->id());
                glProgramUniform3fv(program, 8, 1, glm::value_ptr(grid.corner));
                glProgramUniform3fv(program, 9, 1, glm::value_ptr(grid.extent));
                glProgramUniform1f(program, 10, grid.voxel);
            }
            for (const SliceView& v : views) {
                const int texels = sliceTexels(v, resolution);
                bindSliceLayers(fbo.id(), resources.id(d.slices), v, false);
                setSliceViewUniforms(program, v, texels);
                // FullscreenPass::draw binds the framebuffer again with the same attachments.
                pass.draw(fbo.id(), {texels, texels}, kSliceAdd);
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
