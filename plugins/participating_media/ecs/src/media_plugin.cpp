#include "nimbus/media/ecs/media_plugin.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "nimbus/base/error.h"
#include "nimbus/base/log.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/frame_info.h"
#include "nimbus/media/emitter_scene.h"
#include "nimbus/media/nimbus/assets_document.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/components.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::media::ecs {
namespace {

using nimbus::ecs::Entity;
using nimbus::ecs::World;

void spawnMediaEntities(World& world, const assets::Scene& scene, const MediaScene& media);

std::string settingText(const nlohmann::json& value) {
    if (value.is_boolean()) return value.get<bool>() ? "on" : "off";
    if (value.is_string()) return value.get<std::string>();
    return value.dump();  // numbers as written
}

// A node's "render" object holds scene defaults for the renderer's settings (docs/scene-format.md
// §3.5): the command line's --set wins, two nodes may not disagree, and every value is checked now,
// at load, by the same parser the renderer uses.
void applyRenderOverrides(World& world, const assets::Scene& scene, const MediaScene& media) {
    auto* settings = world.tryResource<Settings>();
    if (settings == nullptr) return;
    std::map<std::string, std::pair<std::string, std::string>> seen;  // key → (value, where)
    for (const MediaNode& node : media.nodes) {
        if (node.render.is_null()) continue;
        const std::string where = scene.displayName() + ": node \"" + node.name + "\" (nodes[" + std::to_string(node.node) +
                                  "]): extensions.NIMBUS_participating_media.render";
        if (!node.render.is_object()) throwInputError(where, "", "", "must be an object");
        for (auto it = node.render.begin(); it != node.render.end(); ++it) {
            const std::string value = settingText(it.value());
            const std::string origin = where + "." + it.key();
            if (const auto previous = seen.find(it.key()); previous != seen.end() && previous->second.first != value)
                throwInputError(origin, "", "", "'" + value + "' disagrees with " + previous->second.second + " ('" +
                                                    previous->second.first + "'): the renderer has one value per frame");
            seen.emplace(it.key(), std::make_pair(value, origin));
            settings->setDefault(it.key(), value, origin);
        }
    }
    (void)readMediaSettings(world);  // a bad value is refused at load, naming the node and field
}

void spawnMedia(World& world, const assets::Scene& scene) {
    const MediaScene media = parseMediaScene(AssetsDocument(scene));  // throws before anything is added
    if (media.empty()) return;
    // A refused scene must leave no setting behind either (spawnScene undoes the entities).
    std::optional<Settings> before;
    if (const auto* settings = world.tryResource<Settings>()) before = *settings;
    try {
        spawnMediaEntities(world, scene, media);
    } catch (...) {
        if (before) world.resource<Settings>() = *before;
        throw;
    }
}

void spawnMediaEntities(World& world, const assets::Scene& scene, const MediaScene& media) {
    applyRenderOverrides(world, scene, media);
    std::vector<Entity> byNode(scene.nodes.size(), nimbus::ecs::kNullEntity);
    world.view<scene::SceneNode>().each([&](Entity e, const scene::SceneNode& node) {
        if (node.node >= 0 && static_cast<std::size_t>(node.node) < byNode.size()) byNode[static_cast<std::size_t>(node.node)] = e;
    });
    for (const MediaNode& node : media.nodes) {
        const Entity e = byNode.at(static_cast<std::size_t>(node.node));
        if (e == nimbus::ecs::kNullEntity) continue;  // outside the displayed scene: not drawn, as its mesh is not
        world.emplace<MediumComponent>(e, MediumComponent{node.medium});
        if (!node.localPositions.empty() && !hasUniformScale(world.get<scene::Transform>(e).world))
            log::warn(scene.displayName() + ": node \"" + node.name + "\": non-uniform scale on a particle cloud; radii use the mean scale");
        if (!node.localPositions.empty())
            world.emplace<ParticleCloud>(e, ParticleCloud{node.localPositions, node.radii, node.densities});
        if (node.volume) world.emplace<VolumeComponent>(e, VolumeComponent{*node.volume, node.origin});
        if (!node.emitter.is_null())
            world.emplace<EmitterComponent>(e, EmitterComponent{EmitterSimulation(parseNodeEmitter(AssetsDocument(scene), node), node.node),
                                                                world.get<scene::Transform>(e).world});
    }
}

// One fixed step for every emitter: [k·dt, (k+1)·dt] with the node's transform at both ends (the
// animation system has already moved it to the end). t0 comes from FrameInfo as k·dt, a product,
// exactly as simulateEmittersTo computes it, so both paths give bit-identical particles.
void emitSystem(World& world) {
    if (world.count<EmitterComponent>() == 0) return;
    const auto& frame = world.resource<nimbus::ecs::FrameInfo>();
    world.view<EmitterComponent, const scene::Transform>().each([&](Entity, EmitterComponent& emitter, const scene::Transform& transform) {
        emitter.simulation.step(frame.time, frame.timeStep, emitter.previousWorld, transform.world);
        emitter.previousWorld = transform.world;
    });
}

void gatherSystem(World& world) {
    auto& frame = world.resource<MediaFrame>();
    frame.particles.clear();
    frame.volumes.clear();
    if (world.count<MediumComponent>() == 0) return;
    frame.settings = readMediaSettings(world);
    gatherParticles(world, frame.particles);
    gatherVolumes(world, frame.volumes);
}

void renderSystem(World& world) {
    auto& frame = world.resource<MediaFrame>();
    auto& state = world.resource<MediaRendererState>();
    auto* extensions = world.tryResource<render::RenderExtensions>();
    if (extensions == nullptr) return;  // a host without the render plugin: nothing to draw into
    auto& list = extensions->list;
    const bool active = !frame.particles.empty() || !frame.volumes.empty();
    if (!active && !state.renderer) return;
    if (!state.renderer) {
        state.renderer = std::make_unique<MediaRenderer>(world.resource<MediaTechniques>().table);
        state.extension = std::make_unique<MediaRenderExtension>(*state.renderer);
    }
    auto registered = std::find(list.begin(), list.end(), state.extension.get());
    if (active && registered == list.end()) list.push_back(state.extension.get());
    if (!active && registered != list.end()) list.erase(registered);
    state.renderer->prepare(frame.particles, frame.settings, &frame.volumes);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> QualityRung::assignments() const {
    std::vector<std::pair<std::string, std::string>> out{{"quality", qualityTierName(tier)}};
    if (mediaScale > 0.0f) out.emplace_back("media_scale", formatSettingNumber(mediaScale));
    return out;
}

MediaRenderSettings readMediaSettings(const Settings* settings, const TechniqueTable* techniques) {
    const TechniqueTable builtIn = techniques ? TechniqueTable{} : builtInTechniques();
    const TechniqueTable& table = techniques ? *techniques : builtIn;
    if (settings == nullptr) return mediaSettingsForTier(QualityTier::Exact, table);
    return media::readMediaSettings(*settings, table);
}

MediaRenderSettings readMediaSettings(World& world) {
    const TechniqueTable& table = world.resource<MediaTechniques>().table;
    const auto* settings = world.tryResource<Settings>();
    if (settings == nullptr) return mediaSettingsForTier(QualityTier::Exact, table);
    return media::readMediaSettings(*settings, table);
}

void refuseIdleSettings(World& world) {
    const auto* settings = world.tryResource<Settings>();
    if (settings == nullptr) return;
    const auto* asset = world.tryResource<scene::SceneAsset>();
    const bool multiple = asset == nullptr || asset->scene == nullptr || asset->scene->environment.scattering == assets::Scattering::Multiple;
    for (const IdleSetting& idle : idleSettings(*settings, world.resource<MediaTechniques>().table, multiple)) {
        if (settings->isDefault(idle.key)) log::warn(describeInputProblem(settings->origin(idle.key), "", "", idle.why + "; ignored"));
        else throwInputError(settings->origin(idle.key), idle.key, "", idle.why);
    }
}

void gatherParticles(World& world, ParticleSet& out) {
    // Static clouds then emitters, each in glTF node order, as media::particlesAtTime does: views
    // visit entities in storage order, so sort by node to make the set independent of it.
    auto inNodeOrder = [&]<typename Component>() {
        std::vector<std::pair<int, Entity>> entities;
        world.view<const MediumComponent, const Component, const scene::SceneNode>().each(
            [&](Entity e, const MediumComponent&, const Component&, const scene::SceneNode& node) { entities.emplace_back(node.node, e); });
        std::sort(entities.begin(), entities.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        return entities;
    };
    for (const auto& [node, e] : inNodeOrder.template operator()<ParticleCloud>()) {
        const ParticleCloud& cloud = world.get<ParticleCloud>(e);
        appendCloudParticles(out, world.get<MediumComponent>(e).medium, cloud.positions, cloud.radii, cloud.densities,
                             world.get<scene::Transform>(e).world);
    }
    for (const auto& [node, e] : inNodeOrder.template operator()<EmitterComponent>())
        world.get<EmitterComponent>(e).simulation.appendParticles(out, world.get<MediumComponent>(e).medium);
}

void gatherVolumes(World& world, std::vector<Volume>& out) {
    const auto* asset = world.tryResource<scene::SceneAsset>();
    const double time = asset != nullptr ? asset->time : 0.0;  // the time the nodes are posed at: the noise drifts to it
    std::vector<std::pair<int, Entity>> entities;
    world.view<const VolumeComponent, const scene::SceneNode>().each(
        [&](Entity e, const VolumeComponent&, const scene::SceneNode& node) { entities.emplace_back(node.node, e); });
    std::sort(entities.begin(), entities.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [node, e] : entities) {
        const VolumeComponent& v = world.get<VolumeComponent>(e);
        out.push_back(makeVolume(v.desc, world.get<scene::Transform>(e).world, world.get<MediumComponent>(e).medium, v.origin, time));
    }
}

void MediaPlugin::build(nimbus::ecs::App& app) {
    app.addPlugin<scene::ScenePlugin>();
    app.addPlugin<render::RenderPlugin>();  // draws nothing until a host enables rendering
    app.registerComponent<MediumComponent>("Medium");
    app.registerComponent<ParticleCloud>("ParticleCloud");
    app.registerComponent<VolumeComponent>("Volume");
    app.registerComponent<EmitterComponent>("Emitter");
    app.insertResource<MediaFrame>();
    app.insertResource<MediaRendererState>();
    if (!app.hasResource<Settings>()) app.insertResource<Settings>();
    app.insertResource<MediaTechniques>(MediaTechniques{techniques_});
    declareMediaSettings(app.resource<Settings>(), techniques_);
    app.resource<scene::SceneSpawners>().add("media", spawnMedia);
    app.addSystem({.name = kEmitSystem, .phase = nimbus::ecs::phases::kSimulate, .after = {scene::kAnimateSystem}}, emitSystem);
    app.addSystem({.name = kLightSliceSystem, .phase = nimbus::ecs::phases::kPrepare}, gatherSystem);
    app.addSystem({.name = kRenderSystem, .phase = nimbus::ecs::phases::kRender, .before = {render::kRenderFrameSystem}},
                  renderSystem);
}

}  // namespace nimbus::media::ecs
