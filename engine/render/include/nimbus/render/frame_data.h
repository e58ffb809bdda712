#pragma once
// The engine's per-frame uniform blocks (gpu/frame_layout.h: camera, lights, mesh shadow views),
// packed from the scene's camera, environment and lights and bound at their fixed points.
#include <vector>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/render/light_views.h"
#include "nimbus/render/view.h"

namespace nimbus::render {

using gpu::GpuFrame;
using gpu::GpuLight;
using gpu::GpuLightView;
using gpu::kFrameUniformBinding;
using gpu::kLightsBinding;
using gpu::kMaxLights;
using gpu::kMaxLightViews;
using gpu::kSceneDepthUnit;
using gpu::kShadowMapUnit;
using gpu::kShadowViewsBinding;
using gpu::packLightView;

// Owns the buffers and rewrites them each frame.
// The scene's fog as the shaders take it; `zfar` (0: infinite) is where background rays stop
// seeing fog when the fog gives no `end`.
gpu::FogParams fogParams(const assets::Fog& fog, double zfar);

class FrameData {
public:
    FrameData();
    void update(const View& view, const assets::Environment& environment, const std::vector<assets::ResolvedLight>& lights,
                const std::vector<std::vector<LightView>>& shadowViews, int shadowMapSize, int pointShadowSize, int pcfRadius);
    void bind() const;  // binds the blocks at their binding points

    const GpuFrame& frame() const { return frame_; }

private:
    GpuFrame frame_{};
    gpu::Buffer frameBuffer_;
    gpu::Buffer lights_, shadowViews_;
};

}  // namespace nimbus::render
