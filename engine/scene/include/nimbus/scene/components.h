#pragma once
// Components for a glTF scene living in the ECS: plain structs, one per concern.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/ecs/world.h"

namespace nimbus::scene {

// Where an entity sits in the world (double: scenes far from the origin stay exact).
struct Transform {
    glm::dmat4 world{1.0};
};

// The glTF node an entity was spawned from; the animation system rewrites its Transform.
struct SceneNode {
    int node = -1;
    std::string name;
};

struct MeshRenderer {
    int mesh = -1;  // index into the scene's meshes
};

struct CameraComponent {
    assets::Camera params;
};

struct LightComponent {
    assets::Light params;
};

// Resource: the loaded scene every system reads (shared so a reload can swap it atomically).
struct SceneAsset {
    std::shared_ptr<const assets::Scene> scene;
    double time = 0.0;  // seconds the nodes are posed at: the spawn time, then each update's end
};

// Resource: what plugins add to a spawned scene. spawnScene() calls each after creating the node
// entities, in registration order; a spawner throws InputError for data it refuses, and then
// nothing of the scene is kept (never half-loaded).
struct SceneSpawners {
    using Spawner = std::function<void(ecs::World&, const assets::Scene&)>;
    std::vector<std::pair<std::string, Spawner>> list;
    void add(std::string name, Spawner spawner) {
        for (const auto& [existing, _] : list)
            if (existing == name) return;
        list.emplace_back(std::move(name), std::move(spawner));
    }
};

}  // namespace nimbus::scene
