// Light slices in deposit form, second pass: per view, the running sum of its slabs written as the
// optical depth up to each slice plane, 4 slices per RGBA32F layer (shaders/media/slices/light_slice_prefix.frag);
// a crop's sum starts from its seed.
#include <algorithm>
#include <string>

#include "slices/light_slice_prefix_pass.h"

#include "nimbus/media/gpu_bindings.h"
#include "planning/slice_crop.h"

namespace nimbus::media {

namespace {
constexpr GLint kSeedSlabLocation = 2;  // light_slice_prefix.frag uSeedSlab ..
constexpr GLint kSeedFirstSlabLocation = 3;
constexpr GLint kSeedShareLocation = 4;
constexpr GLint kSeedUvLocation = 5;

// A crop's seed (planning/slice_crop.h): where its first plane falls among its whole view's planes,
// and its uv in the whole view's, as mediaCropClip maps them the other way
// (shaders/media/host/light_transmittance.glsl). `firstSlab`: the whole view's.
void setSeedUniforms(GLuint program, const SliceView& crop, const SliceView& whole, int firstSlab) {
    const gpu::LightView &c = crop.view, &w = whole.view;
    const double first = cropFirstPlane(c, crop.slices);
    const double at = std::clamp((first - w.depthNear) / (static_cast<double>(w.depthFar) - w.depthNear) * whole.slices, 0.0,
                                 static_cast<double>(whole.slices));
    const int slab = std::min(static_cast<int>(at), whole.slices - 1);
    const glm::vec2 scale = c.halfExtent / w.halfExtent;
    const glm::vec2 offset = 0.5f * ((-1.0f - glm::vec2(c.viewProjection[3])) * scale + glm::vec2(w.viewProjection[3]) + 1.0f);
    glProgramUniform1i(program, kSeedSlabLocation, firstSlab + slab);
    glProgramUniform1i(program, kSeedFirstSlabLocation, firstSlab);
    glProgramUniform1f(program, kSeedShareLocation, static_cast<float>(at - slab));
    glProgramUniform4f(program, kSeedUvLocation, scale.x, scale.y, offset.x, offset.y);
}
}  // namespace

LightSlicePrefixPass::LightSlicePrefixPass() = default;

const gpu::FullscreenPass& LightSlicePrefixPass::passFor(int slices) {
    std::unique_ptr<gpu::FullscreenPass>& pass = passes_.at(static_cast<std::size_t>(slices));
    if (!pass)
        pass = std::make_unique<gpu::FullscreenPass>("media/slices/light_slice_prefix.frag",
                                                     std::vector<std::string>{"SLICES " + std::to_string(slices)});
    return *pass;
}

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
            std::vector<int> firstSlab{0};
            for (const SliceView& v : views) firstSlab.push_back(firstSlab.back() + v.slices);
            for (std::size_t i = 0; i < views.size(); ++i) {
                const SliceView& v = views[i];
                const gpu::FullscreenPass& pass = passFor(v.slices);
                const GLuint program = pass.program();
                bindSliceLayers(fbo.id(), resources.id(d.slices), v);
                glProgramUniform1i(program, 0, firstSlab[i]);
                if (v.seedView >= 0)
                    setSeedUniforms(program, v, views[static_cast<std::size_t>(v.seedView)], firstSlab[static_cast<std::size_t>(v.seedView)]);
                else
                    glProgramUniform1i(program, kSeedSlabLocation, -1);
                pass.draw(fbo.id(), glm::ivec2(sliceTexels(v, resolution)));
                unbindSliceLayers(fbo.id(), v);
            }
        });
    return data.slices;
}

}  // namespace nimbus::media
