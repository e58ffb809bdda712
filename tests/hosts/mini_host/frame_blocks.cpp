#include "frame_blocks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mini {
namespace gpu = nimbus::gpu;
namespace {

LightBlock packLight(const gpu::PunctualLight& l, const glm::dvec3& origin, int firstView, int views) {
    LightBlock b{};
    b.position = glm::vec4(glm::vec3(l.position - origin), static_cast<float>(l.range));
    const float kind = l.kind == gpu::LightKind::Directional ? 0.0f : l.kind == gpu::LightKind::Point ? 1.0f : 2.0f;
    b.direction = glm::vec4(glm::vec3(l.direction), kind);
    b.radiance = glm::vec4(l.radiance, 0.0f);
    // KHR_lights_punctual's cone falloff as a = clamp(cosθ·scale + offset, 0, 1).
    const double cosInner = std::cos(l.innerConeAngle), cosOuter = std::cos(l.outerConeAngle);
    const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
    b.spot = glm::vec4(static_cast<float>(scale), static_cast<float>(-cosOuter * scale), static_cast<float>(firstView),
                       static_cast<float>(views));
    return b;
}

ShadowViewBlock packShadowView(const gpu::LightView& v, int layer) {
    ShadowViewBlock b{};
    b.view = v.view;
    b.viewProjection = v.viewProjection;
    const float texel = 2.0f * v.halfExtent.x / static_cast<float>(kShadowMapSize);  // sizes the normal-offset bias
    b.params = glm::vec4(v.perspective ? 1.0f : 0.0f, texel, static_cast<float>(layer), 0.0f);
    return b;
}

template <class T>
void write(const gpu::Buffer& buffer, const std::vector<T>& items, std::size_t capacity, const char* what) {
    if (items.size() > capacity)
        throw std::runtime_error(std::to_string(items.size()) + " " + what + "; mini_host draws at most " + std::to_string(capacity));
    if (!items.empty()) glNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(items.size() * sizeof(T)), items.data());
}

}  // namespace

FrameBlocks::FrameBlocks()
    : frame_(gpu::createBuffer(sizeof(FrameBlock))),
      lights_(gpu::createBuffer(kMaxLights * sizeof(LightBlock))),
      shadowViews_(gpu::createBuffer(kMaxShadowViews * sizeof(ShadowViewBlock))) {}

void FrameBlocks::upload(const FrameInput& f) {
    std::vector<LightBlock> lights;
    std::vector<ShadowViewBlock> views;
    for (std::size_t i = 0; i < f.lights.size(); ++i) {
        const auto& lightViews = f.shadowViews.at(i);
        const int first = lightViews.empty() ? -1 : static_cast<int>(views.size());
        lights.push_back(packLight(f.lights[i], f.view.origin, first, static_cast<int>(lightViews.size())));
        for (const auto& v : lightViews) views.push_back(packShadowView(v, static_cast<int>(views.size())));
    }
    write(lights_, lights, kMaxLights, "lights");
    write(shadowViews_, views, kMaxShadowViews, "shadow views");
    const FrameBlock frame{f.opaqueViewProjection, glm::vec4(f.environment.ambient, 0.0f),
                           glm::ivec4(static_cast<int>(lights.size()), kShadowMapSize, kPcfRadius, 0)};
    glNamedBufferSubData(frame_.id(), 0, sizeof(FrameBlock), &frame);
}

void FrameBlocks::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frame_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, lights_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowViewsBinding, shadowViews_.id());
}

}  // namespace mini
