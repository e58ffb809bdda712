// Light slices: the views drawn small scaled up into their layers (light_slice_upscale_pass.h).
#include "slices/light_slice_upscale_pass.h"

#include <string>
#include <vector>

#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

namespace {
constexpr GLint kTargetLayerLocation = 0;  // light_slice_upscale.vert uTargetLayer (layered only)
constexpr GLint kSourceLayerLocation = 1;  // uSourceLayer
constexpr GLint kScaleLocation = 2;        // light_slice_upscale.frag uScale
constexpr GLint kLastLocation = 3;         // uLast
}  // namespace

bool LightSliceUpscalePass::supported() { return epoxy_has_gl_extension("GL_ARB_shader_viewport_layer_array"); }

LightSliceUpscalePass::LightSliceUpscalePass(bool layered)
    : layered_(layered),
      program_(gpu::compileProgram({.vertex = "media/slices/light_slice_upscale.vert",
                                    .fragment = "media/slices/light_slice_upscale.frag",
                                    .defines = layered ? std::vector<std::string>{} : std::vector<std::string>{"UPSCALE_ONE_LAYER"}})) {}

gpu::ResourceHandle LightSliceUpscalePass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                               const LightSlicePass::Output& drawn) {
    if (!drawn.small.valid()) return drawn.slices;
    struct Data {
        gpu::ResourceHandle slices, small;
    };
    const auto& data = graph.addPass<Data>(
        "light_slice_upscale",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slices = builder.write(drawn.slices);
            d.small = builder.read(drawn.small);
        },
        [this, views, resolution, small = drawn.layout](const gpu::PassResources& resources, const Data& d) {
            const GLuint slices = resources.id(d.slices), source = resources.id(d.small);
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            if (layered_) glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, slices, 0);  // layered: gl_Layer picks the layer
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, resolution, resolution);
            gpu::applyPipeline({});
            const GLuint program = program_.id();
            glUseProgram(program);
            glBindTextureUnit(kSmallSlicesUnit, source);
            glBindSampler(kSmallSlicesUnit, bilinear_.id());
            glBindVertexArray(vertexArray_.id());
            for (std::size_t i = 0; i < views.size(); ++i) {
                if (small.smallFirstLayer[i] < 0) continue;
                const SliceView& v = views[i];
                const float side = static_cast<float>(small.size);
                glProgramUniform1f(program, kScaleLocation, static_cast<float>(v.resolution) / (side * static_cast<float>(resolution)));
                glProgramUniform1f(program, kLastLocation, (static_cast<float>(v.resolution) - 0.5f) / side);
                const int layers = (v.slices + 3) / 4;
                if (layered_) {
                    glProgramUniform1i(program, kTargetLayerLocation, v.firstLayer);
                    glProgramUniform1i(program, kSourceLayerLocation, small.smallFirstLayer[i]);
                    glDrawArraysInstanced(GL_TRIANGLES, 0, 3, layers);
                    continue;
                }
                for (int a = 0; a < layers; ++a) {
                    glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, slices, 0, v.firstLayer + a);
                    glProgramUniform1i(program, kSourceLayerLocation, small.smallFirstLayer[i] + a);
                    glDrawArrays(GL_TRIANGLES, 0, 3);
                }
            }
            glBindSampler(kSmallSlicesUnit, 0);
        });
    return data.slices;
}

}  // namespace nimbus::media
