#include "nimbus/render/frame_data.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "nimbus/base/error.h"

namespace nimbus::render {

GpuLightView packLightView(const LightView& v, int firstLayer, float sliceCount, float texels) {
    GpuLightView g{};
    g.view = v.view;
    g.viewProjection = v.viewProjection;
    g.params = glm::vec4(v.perspective ? 1.0f : 0.0f, v.depthNear, v.depthFar, sliceCount);
    // World size of one texel: at depth 1 for perspective views (scale by depth in the shader).
    const float texelSize = 2.0f * v.halfExtent.x / std::max(texels, 1.0f);
    g.params2 = glm::vec4(static_cast<float>(firstLayer), texelSize, v.halfExtent.x, v.halfExtent.y);
    return g;
}

// Uniform blocks are declared at their largest, so the buffers are too.
FrameData::FrameData()
    : frameBuffer_(gpu::createBuffer(sizeof(GpuFrame), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      lights_(gpu::createBuffer(kMaxLights * sizeof(GpuLight), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      shadowViews_(gpu::createBuffer(kMaxLightViews * sizeof(GpuLightView), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      transmittanceViews_(gpu::createBuffer(kMaxLightViews * sizeof(GpuLightView), nullptr, GL_DYNAMIC_STORAGE_BIT)) {}

template <typename T>
void FrameData::upload(gpu::Buffer& buffer, std::size_t capacity, const std::vector<T>& items, const char* what) {
    if (items.size() > capacity)
        throw InputError(std::to_string(items.size()) + " " + what + " in one frame; the real-time renderer draws at most " +
                         std::to_string(capacity));
    if (!items.empty()) glNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(items.size() * sizeof(T)), items.data());
}

void FrameData::update(const View& view, const assets::Environment& environment,
                       const std::vector<assets::ResolvedLight>& lights,
                       const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pcfRadius,
                       const TransmittanceSlices* transmittance) {
    GpuFrame& f = frame_;
    f.viewProjection = view.viewProjection;
    f.view = view.view;
    f.inverseViewProjection = view.inverseViewProjection;
    const bool ortho = view.orthographic;
    f.cameraRight = glm::vec4(glm::vec3(view.right), ortho ? view.orthoHalfExtent.x : view.tanHalfFovY * view.aspect);
    f.cameraUp = glm::vec4(glm::vec3(view.up), ortho ? view.orthoHalfExtent.y : view.tanHalfFovY);
    f.cameraForward = glm::vec4(glm::vec3(view.forward), ortho ? 1.0f : 0.0f);
    f.depthParams = glm::vec4(view.depthLinearization(), view.znear, view.zfar);
    f.viewport = glm::vec4(static_cast<float>(view.width), static_cast<float>(view.height), 1.0f / static_cast<float>(view.width),
                           1.0f / static_cast<float>(view.height));
    f.ambient = glm::vec4(environment.ambient, 0.0f);
    f.background = glm::vec4(environment.background, 0.0f);
    f.counts = glm::ivec4(static_cast<int>(lights.size()), transmittance && !transmittance->views.empty() ? 1 : 0, shadowMapSize,
                          pcfRadius);
    glNamedBufferSubData(frameBuffer_.id(), 0, sizeof(GpuFrame), &f);

    std::vector<GpuLight> gpuLights;
    std::vector<GpuLightView> gpuShadowViews;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const auto& l = lights[i];
        GpuLight g{};
        g.position = glm::vec4(view.toRelative(l.position), static_cast<float>(l.params.range));
        const float type = l.params.type == assets::LightType::Directional ? 0.0f : l.params.type == assets::LightType::Point ? 1.0f : 2.0f;
        g.direction = glm::vec4(glm::vec3(l.direction), type);
        g.radiance = glm::vec4(l.params.color * l.params.intensity, 0.0f);
        const double cosInner = std::cos(l.params.innerConeAngle), cosOuter = std::cos(l.params.outerConeAngle);
        const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
        const auto& views = i < shadowViews.size() ? shadowViews[i] : std::vector<LightView>{};
        g.spot = glm::vec4(static_cast<float>(scale), static_cast<float>(-cosOuter * scale),
                           views.empty() ? -1.0f : static_cast<float>(gpuShadowViews.size()), static_cast<float>(views.size()));
        for (const auto& v : views)
            gpuShadowViews.push_back(packLightView(v, static_cast<int>(gpuShadowViews.size()), 0.0f, static_cast<float>(shadowMapSize)));
        g.media = glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f);
        if (transmittance && i < transmittance->perLight.size() && transmittance->perLight[i].y > 0)
            g.media = glm::vec4(static_cast<float>(transmittance->perLight[i].x), static_cast<float>(transmittance->perLight[i].y), 0, 0);
        gpuLights.push_back(g);
    }
    upload(lights_, kMaxLights, gpuLights, "lights");
    upload(shadowViews_, kMaxLightViews, gpuShadowViews, "shadow map views");
    upload(transmittanceViews_, kMaxLightViews, transmittance ? transmittance->views : std::vector<GpuLightView>{}, "light slice views");
}

void FrameData::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameUniformBinding, frameBuffer_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, lights_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowViewsBinding, shadowViews_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kTransmittanceViewsBinding, transmittanceViews_.id());
}

}  // namespace nimbus::render
