#include "nimbus/render/light_views.h"

namespace nimbus::render {

gpu::PunctualLight punctualLight(const assets::ResolvedLight& light) {
    gpu::PunctualLight p;
    p.kind = light.params.type == assets::LightType::Directional ? gpu::LightKind::Directional
             : light.params.type == assets::LightType::Point     ? gpu::LightKind::Point
                                                                  : gpu::LightKind::Spot;
    p.position = light.position;
    p.direction = light.direction;
    p.radiance = light.params.color * light.params.intensity;
    p.range = light.params.range;
    p.innerConeAngle = light.params.innerConeAngle;
    p.outerConeAngle = light.params.outerConeAngle;
    return p;
}

std::vector<gpu::PunctualLight> punctualLights(const std::vector<assets::ResolvedLight>& lights) {
    std::vector<gpu::PunctualLight> out;
    out.reserve(lights.size());
    for (const auto& l : lights) out.push_back(punctualLight(l));
    return out;
}

}  // namespace nimbus::render
