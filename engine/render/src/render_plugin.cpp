#include "nimbus/render/render_plugin.h"

#include "nimbus/base/quality_tier.h"
#include "nimbus/base/settings.h"

#include "nimbus/scene/components.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::render {
namespace {

// The renderer's keys: shadow filtering, which the fast tier trades for speed.
const SettingField<RenderSettings> kRenderFields[] = {
    {{.key = "shadow_map_size", .help = "mesh shadow map resolution per light view", .type = SettingType::Integer, .min = 64,
      .max = 8192, .defaultValue = "2048 (fast: 1024)"},
     &setInteger<&RenderSettings::shadowMapSize>},
    {{.key = "pcf_radius", .help = "mesh shadow PCF kernel radius in texels", .type = SettingType::Integer, .min = 0, .max = 4,
      .defaultValue = "1: 3x3 taps (fast: 0)"},
     &setInteger<&RenderSettings::pcfRadius>},
    {{.key = "point_shadow_scale",
      .help = "side of a point light's six shadow-map faces as a share of shadow_map_size (each face spans 90 degrees)",
      .type = SettingType::Number, .min = 0.125, .max = 1.0, .defaultValue = "1 (balanced and fast: 0.5)",
      .showsWith = "a point light"},
     &setNumber<&RenderSettings::pointShadowScale>},
};

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
    settings.declare(qualityTierSpec());
    for (const SettingSpec& spec : specsOf(kRenderFields)) settings.declare(spec);
    app.addSystem({.name = kRenderFrameSystem, .phase = ecs::phases::kRender}, renderFrame);
}

void readRenderSettings(const Settings& settings, RenderSettings& out) {
    // Every frame from the tier: a tier switched off must not leave its values behind.
    const bool fast = readQualityTier(settings) == QualityTier::Fast;
    out.shadowMapSize = fast ? 1024 : 0;
    out.pcfRadius = fast ? 0 : -1;
    out.pointShadowScale = readQualityTier(settings) == QualityTier::Exact ? 0.0f : 0.5f;
    out = readFields<RenderSettings>(settings, kRenderFields, out);
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
