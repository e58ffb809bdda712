#include "modules/transform_module.h"

#include <algorithm>
#include <utility>

#include "animation.h"

namespace mini {
namespace {

// Depth of every node below its glTF parent (iterative: a deep hierarchy must not overflow the stack).
std::vector<int> nodeDepths(const Scene& scene) {
    std::vector<int> depth(scene.nodes.size(), -1);
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        std::vector<std::size_t> chain;
        std::size_t n = i;
        while (depth[n] < 0 && chain.size() <= scene.nodes.size()) {  // bounded in case of a cycle
            chain.push_back(n);
            if (scene.nodes[n].parent < 0) break;
            n = static_cast<std::size_t>(scene.nodes[n].parent);
        }
        int d = depth[n] >= 0 ? depth[n] + 1 : 0;
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth[*it] = d++;
    }
    return depth;
}

void spawn(ecs::World& world) {
    if (world.trySingleton<SceneAsset>() != nullptr) return;  // loaded by an earlier frame
    auto scene = std::make_shared<const Scene>(loadScene(world.singleton<SceneRequest>().file));
    const std::vector<int> depth = nodeDepths(*scene);
    SceneAsset asset{scene, {}};
    for (std::size_t i = 0; i < scene->nodes.size(); ++i) {
        const Node& node = scene->nodes[i];
        const ecs::Entity e = world.entity();
        asset.nodeEntities.push_back(e);
        world.add(e, NodeIndex{static_cast<int>(i)});
        world.add(e, LocalTransform{node.pose, node.hasMatrix, node.matrix});
        world.add(e, HierarchyDepth{depth[i]});
        world.add(e, WorldTransform{});
        if (scene->shown[i]) world.add(e, Shown{});
        if (node.mesh >= 0) world.add(e, MeshRef{node.mesh});
        if (node.camera >= 0) world.add(e, CameraRef{node.camera});
        if (node.light >= 0) world.add(e, LightRef{node.light});
        if (!node.media.is_null()) world.add(e, MediaNode{node.media});
    }
    for (std::size_t i = 0; i < scene->nodes.size(); ++i)
        if (const int p = scene->nodes[i].parent; p >= 0) world.add(asset.nodeEntities[i], Parent{asset.nodeEntities[static_cast<std::size_t>(p)]});
    world.set(std::move(asset));
}

void sampleAnimations(ecs::World& world) {
    const SceneAsset& asset = world.singleton<SceneAsset>();
    const double time = world.singleton<SceneRequest>().time;
    world.each<NodeIndex, LocalTransform>([&](ecs::Entity, const NodeIndex& node, LocalTransform& local) {
        local.pose = asset.scene->nodes[static_cast<std::size_t>(node.index)].pose;
    });
    // All animations play together; a later channel on the same node and path wins.
    for (const Channel& channel : asset.scene->channels) {
        if (channel.node < 0 || static_cast<std::size_t>(channel.node) >= asset.nodeEntities.size()) continue;
        LocalTransform* local = world.get<LocalTransform>(asset.nodeEntities[static_cast<std::size_t>(channel.node)]);
        if (local == nullptr || local->hasMatrix) continue;  // glTF: matrix nodes are not animated
        applyChannel(channel, sampleChannel(channel, time), local->pose);
    }
}

void propagate(ecs::World& world) {
    std::vector<std::pair<int, ecs::Entity>> order;
    world.each<HierarchyDepth, LocalTransform, WorldTransform>(
        [&](ecs::Entity e, const HierarchyDepth& d, LocalTransform&, WorldTransform&) { order.emplace_back(d.depth, e); });
    std::sort(order.begin(), order.end());  // parents before children
    for (const auto& [depth, e] : order) {
        const LocalTransform* local = world.get<LocalTransform>(e);
        WorldTransform* out = world.get<WorldTransform>(e);
        if (local == nullptr || out == nullptr) continue;
        const glm::dmat4 matrix = local->hasMatrix ? local->matrix : poseMatrix(local->pose);
        const Parent* parent = world.get<Parent>(e);
        const WorldTransform* parentWorld = parent != nullptr ? world.get<WorldTransform>(parent->entity) : nullptr;
        out->matrix = parentWorld != nullptr ? parentWorld->matrix * matrix : matrix;
    }
}

}  // namespace

void TransformModule::import(ecs::World& world) {
    world.component<NodeIndex>();
    world.component<LocalTransform>();
    world.component<WorldTransform>();
    world.system("scene.spawn", ecs::Phase::OnLoad, spawn);
    world.system("animation.sample", ecs::Phase::OnUpdate, sampleAnimations);
    world.system("transform.propagate", ecs::Phase::OnUpdate, propagate);
}

}  // namespace mini
