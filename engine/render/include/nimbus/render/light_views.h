#pragma once
// A scene's lights as the small GL part's punctual lights, and the views from them (gpu/light_views.h).
#include <vector>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::render {

using gpu::LightView;
using gpu::cubeFace;
using gpu::cubeFaceView;
using gpu::isCubeFaceView;
using gpu::lightViewDepth;

gpu::PunctualLight punctualLight(const assets::ResolvedLight& light);
std::vector<gpu::PunctualLight> punctualLights(const std::vector<assets::ResolvedLight>& lights);

inline std::vector<LightView> makeLightViews(const assets::ResolvedLight& light, const assets::Aabb& bounds, const glm::dvec3& origin) {
    return gpu::makeLightViews(punctualLight(light), bounds, origin);
}

}  // namespace nimbus::render
