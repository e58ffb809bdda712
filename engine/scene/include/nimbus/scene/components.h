#pragma once
// Components for a glTF scene living in the ECS: plain structs, one per concern.
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"

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
};

}  // namespace nimbus::scene
