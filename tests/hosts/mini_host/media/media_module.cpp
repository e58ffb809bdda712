#include "media/media_module.h"

#include <algorithm>
#include <cmath>

#include "media/tiny_document.h"
#include "modules/components.h"
#include "modules/render_module.h"
#include "nimbus/media/emitter_scene.h"

namespace mini {
namespace media = nimbus::media;
namespace {

void spawn(ecs::World& world) {
    const SceneAsset& asset = world.singleton<SceneAsset>();
    MediaState& state = world.singleton<MediaState>();
    state.document = std::make_unique<TinyDocument>(asset.scene);
    state.scene = media::parseMediaScene(*state.document);  // refuses a bad extension with file, node and field
    for (std::size_t i = 0; i < state.scene.nodes.size(); ++i) {
        const media::MediaNode& node = state.scene.nodes[i];
        const ecs::Entity entity = asset.nodeEntities.at(static_cast<std::size_t>(node.node));
        if (!node.localPositions.empty()) world.add<StaticCloud>(entity, StaticCloud{i});
        if (node.volume) world.add<VolumeNode>(entity, VolumeNode{i});
        if (!node.emitter.is_null())
            world.add<Emitter>(entity, Emitter{i, media::EmitterSimulation(media::parseNodeEmitter(*state.document, node), node.node)});
    }
}

// Steps k cover [k·dt, (k+1)·dt] with the node's world transform at both ends, as the plugin's
// simulateEmittersTo does, so a frame at time T holds the particles any host computes for T.
void emit(ecs::World& world) {
    const double time = world.singleton<SceneRequest>().time;
    const MediaState& state = world.singleton<MediaState>();
    const double dt = media::kEmitterTimeStep;
    const long long target = std::llround(time / dt);
    world.each<Emitter>([&](ecs::Entity, Emitter& e) {
        if (e.steps >= target) return;
        const auto node = static_cast<std::size_t>(state.scene.nodes[e.mediaNode].node);
        glm::dmat4 world0 = state.document->worldTransforms(static_cast<double>(e.steps) * dt)[node];
        for (; e.steps < target; ++e.steps) {
            const glm::dmat4 world1 = state.document->worldTransforms(static_cast<double>(e.steps + 1) * dt)[node];
            e.simulation.step(static_cast<double>(e.steps) * dt, dt, world0, world1);
            world0 = world1;
        }
    });
}

// Entities with component C in media-node order (which is glTF node order).
template <class C>
std::vector<std::pair<std::size_t, ecs::Entity>> inMediaOrder(ecs::World& world) {
    std::vector<std::pair<std::size_t, ecs::Entity>> out;
    world.each<C>([&](ecs::Entity e, C& c) { out.push_back({c.mediaNode, e}); });
    std::sort(out.begin(), out.end());
    return out;
}

void gather(ecs::World& world) {
    MediaState& state = world.singleton<MediaState>();
    state.particles.clear();
    for (const auto& [index, entity] : inMediaOrder<StaticCloud>(world)) {
        const media::MediaNode& node = state.scene.nodes[index];
        media::appendCloudParticles(state.particles, node.medium, node.localPositions, node.radii, node.densities,
                                    world.get<WorldTransform>(entity)->matrix);
    }
    for (const auto& [index, entity] : inMediaOrder<Emitter>(world))
        world.get<Emitter>(entity)->simulation.appendParticles(state.particles, state.scene.nodes[index].medium);
    state.volumes.clear();
    for (const auto& [index, entity] : inMediaOrder<VolumeNode>(world)) {
        const media::MediaNode& node = state.scene.nodes[index];
        state.volumes.push_back(media::makeVolume(*node.volume, world.get<WorldTransform>(entity)->matrix, node.medium, node.origin,
                                                  world.singleton<SceneRequest>().time));
    }
    if (state.empty()) return;
    if (!state.renderer) state.renderer = std::make_unique<media::MediaRenderer>();
    state.renderer->prepare(state.particles, world.singleton<MediaSettings>().settings, &state.volumes);
}

// World boxes of the instances' meshes, which blocks mode shades exactly where they reach.
std::vector<media::OccluderBox> occluderBoxes(const FrameInput& frame, const Scene& scene) {
    std::vector<media::OccluderBox> boxes;
    for (const MeshInstance& instance : frame.instances) {
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(instance.mesh));
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const Primitive& p : mesh.primitives) {
            lo = glm::min(lo, glm::dvec3(p.boundsMin));
            hi = glm::max(hi, glm::dvec3(p.boundsMax));
        }
        if (lo.x <= hi.x) boxes.push_back(media::occluderBox(instance.world, lo, hi));
    }
    return boxes;
}

// The contract's frame from mini_host's: its camera, lights, environment and shadow map, and the
// mesh boxes when the renderer reads them. Made once per frame, before the opaque pass; the scene
// depth joins it after that pass (its target exists from the first opaque pass on).
void makeHostFrame(MediaState& state, const FrameInput& frame, const MeshRenderer& meshes, const Scene& scene) {
    media::HostFrame& host = state.frame;
    host = {};
    host.camera = frame.view;
    host.lights = frame.lights;
    host.ambient = frame.environment.ambient;
    host.background = frame.environment.background;
    state.shadows = {meshes.shadowMap(), kShadowMapSize, kPcfRadius, frame.shadowViews};
    host.shadows = &state.shadows;
    host.depthConvention = frame.standardDepth ? media::DepthConvention::Standard : media::DepthConvention::ReversedZ;
    if (state.renderer->readsOccluders()) {
        host.occluders = occluderBoxes(frame, scene);
        host.occludersComplete = true;  // every mesh's box
    }
}

void installHooks(ecs::World& world) {
    MediaHooks hooks;
    hooks.bounds = [](ecs::World& w) {
        const MediaState& state = w.singleton<MediaState>();
        return state.empty() ? nimbus::Aabb{} : state.renderer->bounds();
    };
    hooks.beforeOpaque = [](ecs::World& w, const FrameInput& frame, const MeshRenderer& meshes) {
        MediaState& state = w.singleton<MediaState>();
        if (state.empty()) return false;
        makeHostFrame(state, frame, meshes, *w.singleton<SceneAsset>().scene);
        const media::LightSlices slices = state.renderer->renderLightSlices(state.frame);
        slices.bind();
        return slices.texture != 0;
    };
    hooks.afterOpaque = [](ecs::World& w, const FrameInput&, const MeshRenderer& meshes) {
        MediaState& state = w.singleton<MediaState>();
        if (state.empty()) return MediaLayerRef{};
        state.frame.sceneDepth = meshes.sceneDepth();
        const media::MediaLayer layer = state.renderer->renderMedia(state.frame);
        return MediaLayerRef{layer.color, layer.size.x, layer.size.y, layer.depthUsed, layer.edgeThreshold, layer.edges, layer.edgeRect};
    };
    world.set(std::move(hooks));
}

}  // namespace

void MediaModule::import(ecs::World& world) {
    if (world.trySingleton<MediaSettings>() == nullptr) world.set(MediaSettings{});
    world.set(MediaState{});
    installHooks(world);
    world.system("media.spawn", ecs::Phase::PostLoad, spawn);
    world.system("media.emit", ecs::Phase::OnUpdate, emit);
    world.system("media.gather", ecs::Phase::PreStore, gather);
}

}  // namespace mini
