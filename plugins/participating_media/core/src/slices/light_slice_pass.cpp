// Light slices: optical depth from each light up to K planes across the medium, exact at the
// planes (shaders/media/light_slices.*). The opaque pass and the media pass read them as T = e^−τ.
#include <algorithm>

#include "slices/light_slice_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"
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
            for (const auto& v : views) drawView(fbo.id(), resources.id(d.slices), v, resolution, buffer);
        });
    return data.slices;
}

void LightSlicePass::drawView(GLuint framebuffer, GLuint slices, const SliceView& v, int resolution, const ParticleGpuBuffer& buffer) {
    const int own = v.resolution > 0 ? std::min(v.resolution, resolution) : resolution;
    const int layers = (v.slices + 3) / 4;
    SliceView target = v;
    GLuint texture = slices;
    if (own < resolution) {  // drawn into the small array's first layers, then scaled up
        if (!small_ || small_.desc().width != own || small_.desc().depth < layers)
            small_ = gpu::Texture({GL_TEXTURE_2D_ARRAY, GL_RGBA32F, own, own, std::max(layers, small_ ? small_.desc().depth : 0), 1});
        target.firstLayer = 0;
        texture = small_.id();
    }
    bindSliceLayers(framebuffer, texture, target);
    setAdditiveSliceState(own);
    setParticleSliceUniforms(program_.id(), v, own);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(buffer.count()));
    unbindSliceLayers(framebuffer, target);
    if (own == resolution) return;
    const gpu::Framebuffer source = gpu::createFramebuffer();
    for (int a = 0; a < layers; ++a) {
        glNamedFramebufferTextureLayer(source.id(), GL_COLOR_ATTACHMENT0, texture, 0, a);
        glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0, slices, 0, v.firstLayer + a);
        glNamedFramebufferReadBuffer(source.id(), GL_COLOR_ATTACHMENT0);
        glNamedFramebufferDrawBuffer(framebuffer, GL_COLOR_ATTACHMENT0);
        glBlitNamedFramebuffer(source.id(), framebuffer, 0, 0, own, own, 0, 0, resolution, resolution, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    }
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace nimbus::media
