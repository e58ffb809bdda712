#pragma once
// ScenePlugin: registers the scene components and the animation system (Simulate phase), which
// moves every spawned node to its glTF-animated pose at the App's simulation time.
// spawnScene() turns a loaded glTF scene into entities (one per node).
//
// Does not: render (RenderPlugin does) or load files (assets::loadScene does).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/ecs/app.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/scene/components.h"

namespace nimbus::scene {

inline constexpr char kAnimateSystem[] = "scene.animate";

class ScenePlugin final : public ecs::Plugin {
public:
    std::string_view name() const override { return "nimbus.scene"; }
    void build(ecs::App& app) override;
};

// One entity per node of the scene (SceneNode + Transform, plus MeshRenderer / CameraComponent /
// LightComponent where the node has them), posed at `time`, then the plugins' SceneSpawners.
// Stores the scene as the SceneAsset resource. If a spawner throws, everything is undone.
void spawnScene(ecs::World& world, std::shared_ptr<const assets::Scene> scene, double time = 0.0);

// Every node's world matrix as the ECS holds it now (indexed by glTF node), for code that needs
// the assets-level view (camera resolution, media parsing).
std::vector<glm::dmat4> currentWorldTransforms(ecs::World& world);

// The simulation clock: the time the World's state corresponds to (updates done × step).
double simulationTime(const ecs::App& app);

// The most fixed steps a simulation to one time may take (docs/scene-format.md §4): at 1/60 s a
// step, about 19 days of scene time. Beyond it a time is absurd, and refused before any work.
inline constexpr std::uint64_t kMaxSimulationSteps = 100'000'000;

// The steps to `time` at `timeStep`, or InputError naming `origin` for a time that is not finite,
// is negative or needs more than kMaxSimulationSteps.
std::uint64_t simulationSteps(double time, double timeStep, const std::string& origin = "time");

// Called every few hundred steps of a long simulation with the steps done and the total.
using SimulationProgress = std::function<void(std::uint64_t done, std::uint64_t total)>;

// Runs App updates until the simulation reaches `time` (fixed steps: the last step ends at
// round(time / step) · step). Only the phases up to and including Simulate run. InputError
// (simulationSteps) for a time it cannot reach.
void simulateTo(ecs::App& app, double time, const SimulationProgress& progress = {});

}  // namespace nimbus::scene
