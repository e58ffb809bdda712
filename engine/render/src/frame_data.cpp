#include "nimbus/render/frame_data.h"

namespace nimbus::render {

// Uniform blocks are declared at their largest, so the buffers are too.
FrameData::FrameData()
    : frameBuffer_(gpu::createBuffer(sizeof(GpuFrame), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      lights_(gpu::createBuffer(kMaxLights * sizeof(GpuLight), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      shadowViews_(gpu::createBuffer(kMaxLightViews * sizeof(GpuLightView), nullptr, GL_DYNAMIC_STORAGE_BIT)) {}

void FrameData::update(const View& view, const assets::Environment& environment, const std::vector<assets::ResolvedLight>& lights,
                       const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pcfRadius) {
    frame_ = gpu::packFrame(view, environment.ambient, environment.background, static_cast<int>(lights.size()), shadowMapSize, pcfRadius);
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(GpuFrame), &frame_);

    std::vector<GpuLight> gpuLights;
    std::vector<GpuLightView> gpuShadowViews;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const auto& views = i < shadowViews.size() ? shadowViews[i] : std::vector<LightView>{};
        const int first = views.empty() ? -1 : static_cast<int>(gpuShadowViews.size());
        gpuLights.push_back(gpu::packLight(punctualLight(lights[i]), view.origin, first, static_cast<int>(views.size())));
        for (const auto& v : views)
            gpuShadowViews.push_back(packLightView(v, static_cast<int>(gpuShadowViews.size()), 0.0f, static_cast<float>(shadowMapSize)));
    }
    gpu::uploadBlock(lights_, kMaxLights, gpuLights, "lights");
    gpu::uploadBlock(shadowViews_, kMaxLightViews, gpuShadowViews, "shadow map views");
}

void FrameData::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameUniformBinding, frameBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, lights_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowViewsBinding, shadowViews_.id());
}

}  // namespace nimbus::render
