// Light slices: optical depth from each light up to K planes across the medium, exact at the
// planes (shaders/media/light_slices.*). The opaque pass and the media pass read them as T = e^−τ.
#include <algorithm>

#include "slices/light_slice_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

namespace {
SmallSliceLayout smallSliceLayout(const std::vector<SliceView>& views, int resolution) {
    SmallSliceLayout layout;
    for (const SliceView& v : views) {
        const bool small = v.resolution > 0 && v.resolution < resolution;
        layout.smallFirstLayer.push_back(small ? layout.layers : -1);
        if (!small) continue;
        layout.layers += (v.slices + 3) / 4;
        layout.size = std::max(layout.size, v.resolution);
    }
    return layout;
}
}  // namespace

LightSlicePass::LightSlicePass() {
    program_ = gpu::compileProgram({.vertex = "media/slices/light_slices.vert", .fragment = "media/slices/light_slices.frag"});
}

LightSlicePass::Output LightSlicePass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                           const ParticleGpuBuffer& buffer) {
    int layers = 0;
    for (const auto& v : views) layers = std::max(layers, v.firstLayer + (v.slices + 3) / 4);
    const SmallSliceLayout small = smallSliceLayout(views, resolution);
    struct Data {
        gpu::ResourceHandle slices, small;
    };
    const auto& data = graph.addPass<Data>(
        "light_slices",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slices = builder.create("light_slices", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, resolution, resolution, layers, 1});
            if (small.layers > 0)
                d.small = builder.create("light_slices_small", {GL_TEXTURE_2D_ARRAY, GL_RGBA32F, small.size, small.size, small.layers, 1});
        },
        [this, views, resolution, small, &buffer](const gpu::PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glUseProgram(program_.id());
            buffer.bindParticles();
            glBindVertexArray(vertexArray_.id());
            for (std::size_t i = 0; i < views.size(); ++i) {
                const SliceView& v = views[i];
                SliceView target = v;
                GLuint texture = resources.id(d.slices);
                int own = resolution;
                if (small.smallFirstLayer[i] >= 0) {
                    target.firstLayer = small.smallFirstLayer[i];
                    texture = resources.id(d.small);
                    own = v.resolution;
                }
                bindSliceLayers(fbo.id(), texture, target);
                setAdditiveSliceState(own);
                setParticleSliceUniforms(program_.id(), v, own);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
                unbindSliceLayers(fbo.id(), target);
            }
        });
    return {data.slices, data.small, small};
}

}  // namespace nimbus::media
