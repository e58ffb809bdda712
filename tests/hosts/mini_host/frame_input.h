#pragma once
// Everything one frame draws, gathered by the render module in PreStore from the world: plain data,
// no GL. Positions are world space in double; the renderer makes them camera-relative.
#include <vector>

#include <glm/glm.hpp>

#include "gltf_scene.h"
#include "nimbus/base/aabb.h"
#include "nimbus/gpu/light_views.h"
#include "nimbus/gpu/view.h"

namespace mini {

struct MeshInstance {
    int mesh = -1;
    glm::dmat4 world{1.0};
};

struct FrameInput {
    nimbus::gpu::View view;
    std::vector<nimbus::gpu::PunctualLight> lights;             // the mesh shader's light indices
    std::vector<std::vector<nimbus::gpu::LightView>> shadowViews;  // per light, one shadow-map layer each
    std::vector<MeshInstance> instances;                        // in node order
    Environment environment;
    nimbus::Aabb meshBounds;    // world boxes of every instance
    nimbus::Aabb shadowBounds;  // what the shadow views cover: meshBounds plus the media's bounds
    bool standardDepth = false;        // the opaque pass's depth: standard (0 near, 1 far) instead of reversed Z
    glm::mat4 opaqueViewProjection{1.0f};  // view.viewProjection, or its standard-depth twin
};

// World bounds of `instances`: a local box's eight corners transformed in double. With one box per
// mesh (around all its primitives) it is what Nimbus fits shadow views to; with one box per
// primitive, what it frames a synthesized camera on. Both conservative.
enum class BoxPer { Mesh, Primitive };
// A projection with `view`'s planes and field of view whose [0, 1] clip depth is standard: 0 at the
// near plane, 1 at the far plane (or infinity), the convention most engines draw with.
glm::mat4 standardProjection(const nimbus::gpu::View& view);

nimbus::Aabb instanceBounds(const Scene& scene, const std::vector<MeshInstance>& instances, BoxPer boxes);

inline constexpr int kShadowMapSize = 2048;  // texels per side of each layer
inline constexpr int kPcfRadius = 1;         // 3×3 taps

}  // namespace mini
