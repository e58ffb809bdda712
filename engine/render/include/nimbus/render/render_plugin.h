#pragma once
// RenderPlugin: draws the ECS scene with SceneRenderer. Its Render-phase system gathers mesh
// instances, lights and the camera from components, lets RenderExtensions (plugins such as the
// participating media) add passes, and renders into SceneRenderer::output().
//
// Does not: create the GL context (the host does, before the first Render phase) or write files.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/render/scene_renderer.h"

namespace nimbus::render {

inline constexpr char kRenderFrameSystem[] = "render.frame";

// Resource: what to render. Rendering is off until the host enables it (simulation-only hosts,
// such as the reference renderer, never do).
struct RenderRequest {
    bool enabled = false;
    RenderSettings settings;
    std::string camera;          // camera or node name; empty: the scene's first camera
    std::optional<assets::ResolvedCamera> cameraOverride;  // a free camera (the editor's), used instead of `camera`
    PassTimer* timer = nullptr;  // per-pass timings when measuring
};

// Resource: the render extensions plugins registered, in registration order.
struct RenderExtensions {
    std::vector<RenderExtension*> list;
};

// Resource: the renderer and the scene's GPU copy, created on the first rendered frame.
struct RendererState {
    std::unique_ptr<SceneRenderer> renderer;
    std::unique_ptr<GpuScene> gpuScene;
    const assets::Scene* uploaded = nullptr;  // the scene gpuScene was made from
    FrameInput lastInput;
};

class RenderPlugin final : public ecs::Plugin {
public:
    std::string_view name() const override { return "nimbus.render"; }
    void build(ecs::App& app) override;
};

// The renderer's settings a Settings resource fixes (shadow_map_size, pcf_radius, directly or
// through a preset); the others keep their values in `out`.
void readRenderSettings(const Settings& settings, RenderSettings& out);

// The frame input the render system would use now (camera, lights, instances), for tools and the
// reference renderer, so every renderer sees the same camera and lights. Needs the SceneAsset.
FrameInput gatherFrameInput(ecs::World& world, const RenderSettings& settings, std::string_view camera,
                            const assets::Aabb& extraBounds);

}  // namespace nimbus::render
