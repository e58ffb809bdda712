#include "nimbus/render/frame_data.h"

#include <cmath>

#include "nimbus/assets/fog.h"

namespace nimbus::render {

// Uniform blocks are declared at their largest, so the buffers are too.
FrameData::FrameData()
    : frameBuffer_(gpu::createBuffer(sizeof(GpuFrame), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      lights_(gpu::createBuffer(kMaxLights * sizeof(GpuLight), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      shadowViews_(gpu::createBuffer(kMaxLightViews * sizeof(GpuLightView), nullptr, GL_DYNAMIC_STORAGE_BIT)) {}

void FrameData::update(const View& view, const assets::Environment& environment, const std::vector<assets::ResolvedLight>& lights,
                       const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pointShadowSize, int pcfRadius) {
    frame_ = gpu::packFrame(view, environment.ambient, environment.background, static_cast<int>(lights.size()), shadowMapSize,
                            pcfRadius, fogParams(environment.fog, view.zfar));
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(GpuFrame), &frame_);

    const gpu::PackedLights packed =
        gpu::packLights(punctualLights(lights), view.origin, shadowViews, shadowMapSize, pointShadowSize);
    gpu::uploadBlock(lights_, kMaxLights, packed.lights, "lights");
    gpu::uploadBlock(shadowViews_, kMaxLightViews, packed.shadowViews, "shadow map views");
}

static_assert(static_cast<int>(assets::FogMode::Height) == static_cast<int>(gpu::FogKind::Height), "the two fog enums share one order");

gpu::FogParams fogParams(const assets::Fog& fog, double zfar) {
    gpu::FogParams out;
    out.kind = static_cast<gpu::FogKind>(static_cast<int>(fog.mode));
    out.color = glm::vec3(fog.color);
    out.density = static_cast<float>(fog.density);
    out.start = static_cast<float>(fog.start);
    out.end = static_cast<float>(fog.end);
    out.falloff = static_cast<float>(fog.falloff);
    out.base = fog.base;
    const double reach = assets::fogBackgroundDistance(fog, zfar);
    out.backgroundDistance = std::isinf(reach) ? 0.0 : reach;
    return out;
}

void FrameData::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameUniformBinding, frameBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, lights_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowViewsBinding, shadowViews_.id());
}

}  // namespace nimbus::render
