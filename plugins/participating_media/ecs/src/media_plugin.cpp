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
    (void)readMediaSettings(settings);  // a bad value is refused at load, naming the node and field
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
        world.emplace<MediumComponent>(e, MediumComponent{node.medium});
        if (!node.localPositions.empty() && !hasUniformScale(world.get<scene::Transform>(e).world))
            log::warn(scene.displayName() + ": node \"" + node.name + "\": non-uniform scale on a particle cloud; radii use the mean scale");
        if (!node.localPositions.empty())
            world.emplace<ParticleCloud>(e, ParticleCloud{node.localPositions, node.radii, node.densities});
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
    if (world.count<MediumComponent>() == 0) return;
    frame.settings = readMediaSettings(world.tryResource<Settings>());
    gatherParticles(world, frame.particles);
}

void renderSystem(World& world) {
    auto& frame = world.resource<MediaFrame>();
    auto& state = world.resource<MediaRendererState>();
    auto* extensions = world.tryResource<render::RenderExtensions>();
    if (extensions == nullptr) return;  // a host without the render plugin: nothing to draw into
    auto& list = extensions->list;
    const bool active = !frame.particles.empty();
    if (!active && !state.renderer) return;
    if (!state.renderer) {
        state.renderer = std::make_unique<MediaRenderer>();
        state.extension = std::make_unique<MediaRenderExtension>(*state.renderer);
    }
    auto registered = std::find(list.begin(), list.end(), state.extension.get());
    if (active && registered == list.end()) list.push_back(state.extension.get());
    if (!active && registered != list.end()) list.erase(registered);
    state.renderer->prepare(frame.particles, frame.settings);
}

}  // namespace

namespace {

bool isQuality(const std::string& text) {
    return std::any_of(std::begin(kQualityPresets), std::end(kQualityPresets), [&](const QualityPreset& p) { return text == p.name; });
}

}  // namespace

MediaRenderSettings readMediaSettings(const Settings* settings) {
    MediaRenderSettings s;
    if (settings == nullptr) return s;
    if (auto v = settings->text("quality"); v && !isQuality(*v))
        throwInputError(settings->origin("quality"), *v, "", "unknown quality (known: fast, balanced, exact)");
    if (auto v = settings->text("mode")) s.mode = parseMediaMode(*v, settings->origin("mode"));
    if (auto v = settings->integer("slices", kMinSlices, kMaxSlices)) s.slices = static_cast<int>(*v);
    if (settings->text("slice_resolution") == "auto") {
        const auto detail = settings->number("slice_detail", 0.25, 16.0);
        s.sliceTexelsPerRadius = detail ? static_cast<float>(*detail) : 3.0f;
    } else if (auto v = settings->integer("slice_resolution", 16, 4096)) {
        s.sliceResolution = static_cast<int>(*v);
    }
    if (auto v = settings->text("lighting")) {
        if (*v == "fragment") s.lighting = ParticleLighting::Fragment;
        else if (*v == "particle") s.lighting = ParticleLighting::Particle;
        else if (*v == "particle_exact") s.lighting = ParticleLighting::ParticleExact;
        else throwInputError(settings->origin("lighting"), *v, "", "unknown lighting (known: fragment, particle, particle_exact)");
    }
    if (settings->text("slice_deposit") == "auto") s.sliceDeposit = SliceDeposit::Auto;
    else if (auto v = settings->boolean("slice_deposit")) s.sliceDeposit = *v ? SliceDeposit::On : SliceDeposit::Off;
    if (auto v = settings->boolean("exact_near_lamps")) s.exactNearLamps = *v;
    if (auto v = settings->boolean("soft_particles")) s.softParticles = *v;
    if (auto v = settings->boolean("layer_light")) s.layerLight = *v;
    if (auto v = settings->integer("blocks", 1, 1 << 20)) s.blocks = static_cast<int>(*v);
    if (auto v = settings->number("impostor_scale", 0.05, 4.0)) s.impostorScale = static_cast<float>(*v);
    if (settings->text("media_scale") == "auto") s.mediaScaleAuto = true;
    else if (auto v = settings->number("media_scale", 0.0625, 1.0)) s.mediaScale = static_cast<float>(*v);
    if (auto v = settings->number("upsample_threshold", 1e-4, 10.0)) s.upsampleThreshold = static_cast<float>(*v);
    if (auto v = settings->boolean("instancing")) s.instancing = *v;
    if (auto v = settings->integer("voxels", 4, 256)) s.voxels = static_cast<int>(*v);
    if (auto v = settings->integer("raymarch_steps", 4, 4096)) s.raymarchSteps = static_cast<int>(*v);
    if (auto v = settings->text("block_shading")) {
        if (*v == "smooth") s.blockShading = BlockShading::Smooth;
        else if (*v == "seam") s.blockShading = BlockShading::Seam;
        else if (*v == "exact") s.blockShading = BlockShading::Exact;
        else throwInputError(settings->origin("block_shading"), *v, "", "unknown block shading (known: smooth, seam, exact)");
    }
    return s;
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

void MediaPlugin::build(nimbus::ecs::App& app) {
    app.addPlugin<scene::ScenePlugin>();
    app.addPlugin<render::RenderPlugin>();  // draws nothing until a host enables rendering
    app.registerComponent<MediumComponent>("Medium");
    app.registerComponent<ParticleCloud>("ParticleCloud");
    app.registerComponent<EmitterComponent>("Emitter");
    app.insertResource<MediaFrame>();
    app.insertResource<MediaRendererState>();
    if (!app.hasResource<Settings>()) app.insertResource<Settings>();
    auto& settings = app.resource<Settings>();
    settings.declare("quality", "fast, balanced or exact (the library's default; sandbox render's is balanced): the settings each picks are in docs/PERFORMANCE.md");
    for (const QualityPreset& preset : kQualityPresets)
        settings.definePreset("quality", preset.name, {preset.settings.begin(), preset.settings.end()});
    settings.declare("mode", "media mode: particles (default), blocks, raymarch (a voxel grid ray-marched per pixel), or billboards (the game-industry yardstick: flat, unshadowed sprites)");
    settings.declare("slices", "light slices per light view, 4..32 (default: chosen from the medium)");
    settings.declare("slice_resolution", "texels per side of a light slice, or auto (chosen from the particles' size as the light sees them; see slice_detail); default 256");
    settings.declare("lighting", "particles mode: where light is evaluated: fragment (default, exact), particle (per particle, linear across it) or particle_exact");
    settings.declare("slice_detail", "with slice_resolution=auto: slice texels across the median particle's radius, 0.25..16 (default 3)");
    settings.declare("slice_deposit", "light slices drawn as one float per particle and slab, then summed: on, off (default) or auto (on unless a point or spot light's views are among them)");
    settings.declare("exact_near_lamps", "with lighting=particle or particle_exact: shade per fragment while a point or spot light lies inside the medium (a particle with a central column over 0.1): on or off (default)");
    settings.declare("soft_particles", "clip particles at opaque surfaces: on (default) or off (billboard plane test)");
    settings.declare("layer_light", "particles mode: light transmittance integrated over each particle: on (default) or off (one point, faster)");
    settings.declare("blocks", "blocks mode: number of particle blocks (default: round(2 sqrt(particles)), more in optically thick media or around a lamp inside them)");
    settings.declare("impostor_scale", "blocks mode: impostor texels per covered pixel, 0.05..4 (default 0.5)");
    settings.declare("media_scale", "resolution of the media pass relative to the frame, e.g. 1, 0.5, 0.25, or auto (where the particles cover the image more than 2.5 times over, 1/4 to 1/2 keeping 8 texels across a typical billboard); default 1");
    settings.declare("instancing", "blocks mode: build the cloud from one block prototype instanced at every block (default off)");
    settings.declare("voxels", "raymarch mode: voxels along the grid's longest side, 4..256 (default: a voxel per third of the small particles' radius, at most 96)");
    settings.declare("raymarch_steps", "raymarch mode: most samples per ray, 4..4096 (default 128)");
    settings.declare("block_shading", "blocks mode, where a mesh is seen in the medium: seam (default: blocks shaded from their particles with the compositing order corrected near the mesh), smooth (faster there, but the mesh can show a seam) or exact (as seam over those blocks' whole rectangles; slowest)");
    settings.declare("upsample_threshold", "offscreen media: relative depth difference treated as an edge (default 0.2)");
    app.resource<scene::SceneSpawners>().add("media", spawnMedia);
    app.addSystem({.name = kEmitSystem, .phase = nimbus::ecs::phases::kSimulate, .after = {scene::kAnimateSystem}}, emitSystem);
    app.addSystem({.name = kLightSliceSystem, .phase = nimbus::ecs::phases::kPrepare}, gatherSystem);
    app.addSystem({.name = kRenderSystem, .phase = nimbus::ecs::phases::kRender, .before = {render::kRenderFrameSystem}},
                  renderSystem);
}

}  // namespace nimbus::media::ecs
