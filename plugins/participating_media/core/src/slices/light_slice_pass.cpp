// Light slices: optical depth from each light up to K planes across the medium, exact at the
// planes (shaders/media/light_slices.*). The opaque pass and the media pass read them as T = e^−τ.
// A view of fewer texels than the array is drawn into its layers' first texels, not the whole
// layer: a fragment costs the same either way, and a lamp's cube faces are covered by the
// particles around it.
#include <algorithm>

#include "slices/light_slice_pass.h"

#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

LightSlicePass::LightSlicePass() {
    program_ = gpu::compileProgram({.vertex = "media/slices/light_slices.vert", .fragment = "media/slices/light_slices.frag"});
}

gpu::ResourceHandle LightSlicePass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                        const ParticleGpuBuffer& buffer) {
    int layers = 0;
    for (const auto& v : views) layers = std::max(layers, v.firstLayer + (v.slices + 3) / 4);
    struct Data {
        gpu::ResourceHandle slices;
    };
    const auto& data = graph.addPass<Data>(
        "light_slices",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slices = builder.create("light_slices", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
        },
        [this, views, resolution, &buffer](const gpu::PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glUseProgram(program_.id());
            buffer.bindParticles();
            glBindVertexArray(vertexArray_.id());
            for (const SliceView& v : views) {
                const int texels = sliceTexels(v, resolution);
                bindSliceLayers(fbo.id(), resources.id(d.slices), v);
                setAdditiveSliceState(texels);
                setParticleSliceUniforms(program_.id(), v, texels);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
