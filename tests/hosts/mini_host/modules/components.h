#pragma once
// The components and singletons mini_host's modules share. A glTF node becomes one entity; which
// optional components it has (mesh, camera, light, media, shown) decides its archetype table.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "ecs/world.h"
#include "gltf_scene.h"

namespace mini {

// ---- components ----
struct NodeIndex {
    int index = -1;  // the glTF node this entity stands for
};
struct Shown {};     // tag: the node is in the displayed glTF scene (drawn, lit, may be the camera)
struct LocalTransform {
    Pose pose;               // rest pose, then animated
    bool hasMatrix = false;  // the node gave a matrix: `matrix` is used and never animated
    glm::dmat4 matrix{1.0};
};
struct Parent {
    ecs::Entity entity = ecs::kNoEntity;
};
struct HierarchyDepth {
    int depth = 0;  // 0 for a root; parents are always shallower, so propagating in depth order works
};
struct WorldTransform {
    glm::dmat4 matrix{1.0};
};
struct MeshRef {
    int mesh = -1;
};
struct CameraRef {
    int camera = -1;
};
struct LightRef {
    int light = -1;
};
struct MediaNode {
    nlohmann::json extension;  // the node's NIMBUS_participating_media object, for the media module
};

// ---- singletons ----
struct SceneRequest {
    std::filesystem::path file;
    double time = 0.0;  // seconds: animations are sampled here
};
struct SceneAsset {
    std::shared_ptr<const Scene> scene;
    std::vector<ecs::Entity> nodeEntities;  // per glTF node
};

}  // namespace mini
