#include "scene_overlays.h"

#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/scene/components.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::sandbox::editor {
namespace {

Aabb meshBox(const assets::Mesh& mesh, const glm::dmat4& world) {
    Aabb box;
    for (const auto& primitive : mesh.primitives)
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 local((corner & 1) ? primitive.boundsMax.x : primitive.boundsMin.x,
                                   (corner & 2) ? primitive.boundsMax.y : primitive.boundsMin.y,
                                   (corner & 4) ? primitive.boundsMax.z : primitive.boundsMin.z);
            box.extend(glm::dvec3(world * glm::dvec4(local, 1.0)));
        }
    return box;
}

void addMediaBoxes(Session& session, std::vector<NodeOverlay>& out) {
    namespace mecs = media::ecs;
    auto& world = session.app().world();
    world.view<scene::SceneNode, scene::Transform, mecs::MediumComponent>().each(
        [&](ecs::Entity entity, const scene::SceneNode& node, const scene::Transform& transform, const mecs::MediumComponent&) {
            NodeOverlay o{node.node, OverlayKind::Media};
            o.position = glm::dvec3(transform.world[3]);
            o.box.extend(o.position);
            if (const auto* cloud = world.tryGet<mecs::ParticleCloud>(entity))
                for (std::size_t i = 0; i < cloud->positions.size(); ++i) {
                    const glm::dvec3 p(transform.world * glm::dvec4(glm::dvec3(cloud->positions[i]), 1.0));
                    const double r = cloud->radii[i] * std::cbrt(std::abs(glm::determinant(glm::dmat3(transform.world))));
                    o.box.extend(p - r);
                    o.box.extend(p + r);
                }
            if (const auto* emitter = world.tryGet<mecs::EmitterComponent>(entity))
                for (const glm::dvec3& p : emitter->simulation.particles().position) {
                    o.box.extend(p - 0.3);  // about a puff's radius: the box is for seeing and picking
                    o.box.extend(p + 0.3);
                }
            out.push_back(o);
        });
}

}  // namespace

std::vector<NodeOverlay> collectOverlays(Session& session) {
    const assets::Scene& scene = session.scene();
    const std::vector<glm::dmat4> world = scene::currentWorldTransforms(session.app().world());
    std::vector<NodeOverlay> out;
    for (std::size_t i = 0; i < scene.nodes.size() && i < world.size(); ++i) {
        const assets::Node& node = scene.nodes[i];
        NodeOverlay o{static_cast<int>(i)};
        o.position = glm::dvec3(world[i][3]);
        o.direction = glm::normalize(-glm::dvec3(world[i][2]));
        if (!(glm::length(o.direction) > 0.0)) o.direction = glm::dvec3(0.0, 0.0, -1.0);
        if (node.mesh >= 0) {
            o.kind = OverlayKind::Mesh;
            o.box = meshBox(scene.meshes[static_cast<std::size_t>(node.mesh)], world[i]);
            out.push_back(o);
        }
        if (node.light >= 0) {
            o.kind = OverlayKind::Light;
            o.directional = scene.lights[static_cast<std::size_t>(node.light)].type == assets::LightType::Directional;
            out.push_back(o);
        }
        if (node.camera >= 0) {
            o.kind = OverlayKind::Camera;
            out.push_back(o);
        }
    }
    addMediaBoxes(session, out);
    return out;
}

glm::dmat4 nodeWorld(Session& session, int node) {
    const auto world = scene::currentWorldTransforms(session.app().world());
    return node >= 0 && static_cast<std::size_t>(node) < world.size() ? world[static_cast<std::size_t>(node)] : glm::dmat4(1.0);
}

glm::dmat4 parentWorld(Session& session, int node) {
    if (node < 0 || static_cast<std::size_t>(node) >= session.scene().nodes.size()) return glm::dmat4(1.0);
    return nodeWorld(session, session.scene().nodes[static_cast<std::size_t>(node)].parent);
}

}  // namespace nimbus::sandbox::editor
