#include "nimbus/render/render_plugin.h"

#include "nimbus/base/settings.h"

#include "nimbus/scene/components.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::render {
namespace {

void renderFrame(ecs::World& world) {
    auto& request = world.resource<RenderRequest>();
    if (!request.enabled) return;
    auto& state = world.resource<RendererState>();
    const auto& asset = world.resource<scene::SceneAsset>();
    if (!state.renderer) state.renderer = std::make_unique<SceneRenderer>();
    if (state.uploaded != asset.scene.get()) {
        state.gpuScene = std::make_unique<GpuScene>(*asset.scene);
        state.uploaded = asset.scene.get();
    }
    if (const auto* settings = world.tryResource<Settings>()) readRenderSettings(*settings, request.settings);
    const auto& extensions = world.resource<RenderExtensions>().list;
    assets::Aabb extra;
    for (auto* e : extensions) extra.extend(e->bounds());
    state.lastInput = gatherFrameInput(world, request.settings, request.camera, extra);
    if (request.cameraOverride) state.lastInput.camera = *request.cameraOverride;
    state.lastInput.gpuScene = state.gpuScene.get();
    state.renderer->render(state.lastInput, request.settings, extensions, request.timer);
}

}  // namespace

void RenderPlugin::build(ecs::App& app) {
    app.addPlugin<scene::ScenePlugin>();
    app.insertResource<RenderRequest>();
    app.insertResource<RenderExtensions>();
    app.insertResource<RendererState>();
    if (!app.hasResource<Settings>()) app.insertResource<Settings>();
    auto& settings = app.resource<Settings>();
    settings.declare("shadow_map_size", "mesh shadow map resolution per light view (default 2048)");
    settings.declare("pcf_radius", "mesh shadow PCF kernel radius in texels, 0..4 (default 1: 3x3 taps)");
    app.addSystem({.name = kRenderFrameSystem, .phase = ecs::phases::kRender}, renderFrame);
}

void readRenderSettings(const Settings& settings, RenderSettings& out) {
    // Unset keys go back to their defaults: a preset switched off must not leave its values behind.
    const auto shadowMapSize = settings.integer("shadow_map_size", 64, 8192);
    const auto pcfRadius = settings.integer("pcf_radius", 0, 4);
    out.shadowMapSize = shadowMapSize ? static_cast<int>(*shadowMapSize) : 0;
    out.pcfRadius = pcfRadius ? static_cast<int>(*pcfRadius) : -1;
}

FrameInput gatherFrameInput(ecs::World& world, const RenderSettings& settings, std::string_view camera,
                            const assets::Aabb& extraBounds) {
    const auto& asset = world.resource<scene::SceneAsset>();
    const assets::Scene& scene = *asset.scene;
    FrameInput input;
    input.environment = scene.environment;
    world.view<scene::MeshRenderer, scene::Transform>().each(
        [&](ecs::Entity, const scene::MeshRenderer& mesh, const scene::Transform& transform) {
            input.instances.push_back({mesh.mesh, transform.world});
        });
    const std::vector<glm::dmat4> pose = scene::currentWorldTransforms(world);
    input.lights = assets::resolveLights(scene, pose);
    assets::Aabb frame = assets::meshBounds(scene, pose);
    frame.extend(extraBounds);
    const int width = settings.width > 0 ? settings.width : 1280;
    const int height = settings.height > 0 ? settings.height : 720;
    input.camera = assets::resolveCamera(scene, pose, camera, frame, static_cast<double>(width) / height);
    return input;
}

}  // namespace nimbus::render
