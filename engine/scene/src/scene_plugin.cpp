#include "nimbus/scene/scene_plugin.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/frame_info.h"

namespace nimbus::scene {
namespace {

// Time the World's state corresponds to after the current update: systems in Simulate advance the
// state from FrameInfo::time to FrameInfo::time + timeStep.
double endOfStep(const ecs::FrameInfo& info) { return static_cast<double>(info.index + 1) * info.timeStep; }

void animate(ecs::World& world) {
    auto* asset = world.tryResource<SceneAsset>();
    if (asset == nullptr) return;
    asset->time = endOfStep(world.resource<ecs::FrameInfo>());
    if (asset->scene == nullptr || asset->scene->animations.empty()) return;
    const std::vector<glm::dmat4> pose = assets::computeWorldTransforms(*asset->scene, asset->time);
    world.view<SceneNode, Transform>().each([&](ecs::Entity, const SceneNode& node, Transform& transform) {
        transform.world = pose.at(static_cast<std::size_t>(node.node));
    });
}

}  // namespace

void ScenePlugin::build(ecs::App& app) {
    app.registerComponent<Transform>("Transform");
    app.registerComponent<SceneNode>("SceneNode");
    app.registerComponent<MeshRenderer>("MeshRenderer");
    app.registerComponent<CameraComponent>("Camera");
    app.registerComponent<LightComponent>("Light");
    if (!app.hasResource<SceneSpawners>()) app.insertResource<SceneSpawners>();
    app.addSystem({.name = kAnimateSystem, .phase = ecs::phases::kSimulate}, animate);
}

void spawnScene(ecs::World& world, std::shared_ptr<const assets::Scene> scene, double time) {
    const std::vector<glm::dmat4> pose = assets::computeWorldTransforms(*scene, time);
    const std::vector<bool> shown = assets::nodesInScene(*scene);
    // What exists before, so a failing spawner can be undone completely (its own entities included).
    std::vector<ecs::Entity> before;
    world.forEachEntity([&](ecs::Entity e) { before.push_back(e); });
    std::shared_ptr<const assets::Scene> previous;
    if (const auto* asset = world.tryResource<SceneAsset>()) previous = asset->scene;

    for (std::size_t i = 0; i < scene->nodes.size(); ++i) {
        if (!shown[i]) continue;  // nodes outside the default scene are not part of what is drawn
        const assets::Node& node = scene->nodes[i];
        const ecs::Entity e = world.create();
        world.emplace<SceneNode>(e, SceneNode{static_cast<int>(i), node.name});
        world.emplace<Transform>(e, Transform{pose[i]});
        if (node.mesh >= 0) world.emplace<MeshRenderer>(e, MeshRenderer{node.mesh});
        if (node.camera >= 0) world.emplace<CameraComponent>(e, CameraComponent{scene->cameras.at(static_cast<std::size_t>(node.camera))});
        if (node.light >= 0) world.emplace<LightComponent>(e, LightComponent{scene->lights.at(static_cast<std::size_t>(node.light))});
    }
    world.insertResource<SceneAsset>(SceneAsset{scene, time});
    if (const auto* spawners = world.tryResource<SceneSpawners>()) {
        try {
            for (const auto& [name, spawn] : spawners->list) spawn(world, *scene);
        } catch (...) {
            std::vector<ecs::Entity> created;
            world.forEachEntity([&](ecs::Entity e) {
                if (std::find(before.begin(), before.end(), e) == before.end()) created.push_back(e);
            });
            for (const ecs::Entity e : created) world.destroy(e);
            if (previous) world.insertResource<SceneAsset>(SceneAsset{previous});
            else world.removeResource<SceneAsset>();
            throw;
        }
    }
}

std::vector<glm::dmat4> currentWorldTransforms(ecs::World& world) {
    const auto& asset = world.resource<SceneAsset>();
    std::vector<glm::dmat4> transforms(asset.scene->nodes.size(), glm::dmat4(1.0));
    world.view<SceneNode, Transform>().each([&](ecs::Entity, const SceneNode& node, const Transform& transform) {
        if (node.node >= 0 && static_cast<std::size_t>(node.node) < transforms.size())
            transforms[static_cast<std::size_t>(node.node)] = transform.world;
    });
    return transforms;
}

double simulationTime(const ecs::App& app) { return static_cast<double>(app.frame()) * app.timeStep(); }

std::uint64_t simulationSteps(double time, double timeStep, const std::string& origin) {
    if (!std::isfinite(time) || time < 0.0)
        throwInputError(origin, formatSettingNumber(time), "", "must be a finite number of seconds >= 0");
    const double steps = std::round(time / timeStep);
    if (!(steps <= static_cast<double>(kMaxSimulationSteps))) {
        char limit[64];
        std::snprintf(limit, sizeof limit, "%.0f s", static_cast<double>(kMaxSimulationSteps) * timeStep);
        throwInputError(origin, formatSettingNumber(time), "",
                        "needs more than " + formatSettingNumber(static_cast<double>(kMaxSimulationSteps)) + " simulation steps of " +
                            formatSettingNumber(timeStep) + " s: at most " + limit + " is simulated");
    }
    return static_cast<std::uint64_t>(steps);
}

void simulateTo(ecs::App& app, double time, const SimulationProgress& progress) {
    const std::uint64_t steps = simulationSteps(time, app.timeStep());
    while (app.frame() < steps) {
        app.update(ecs::phases::kSimulate);
        if (progress && (app.frame() % 256 == 0 || app.frame() == steps)) progress(app.frame(), steps);
    }
}

}  // namespace nimbus::scene
