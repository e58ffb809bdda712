#include "modules/render_module.h"

#include <algorithm>
#include <utility>

#include "camera_lights.h"

namespace mini {
namespace gpu = nimbus::gpu;
namespace {

// Shown entities with component C, in glTF node order (the order Nimbus draws, lights and picks cameras in).
template <class C>
std::vector<std::pair<int, std::pair<C, glm::dmat4>>> inNodeOrder(ecs::World& world) {
    std::vector<std::pair<int, std::pair<C, glm::dmat4>>> out;
    world.each<NodeIndex, C, WorldTransform, Shown>([&](ecs::Entity, const NodeIndex& n, const C& c, const WorldTransform& w, Shown&) {
        out.push_back({n.index, {c, w.matrix}});
    });
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

gpu::View renderCamera(ecs::World& world, const Scene& scene, const RenderRequest& request, const nimbus::Aabb& frame) {
    const auto cameras = inNodeOrder<CameraRef>(world);
    Camera camera;
    glm::dmat4 placement(1.0);
    if (!cameras.empty()) {
        camera = scene.cameras.at(static_cast<std::size_t>(cameras.front().second.first.camera));
        placement = cameras.front().second.second;
    } else {
        framingCamera(frame, static_cast<double>(request.width) / request.height, camera, placement);
    }
    return cameraView(camera, placement, request.width, request.height);
}

void gather(ecs::World& world) {
    const Scene& scene = *world.singleton<SceneAsset>().scene;
    const RenderRequest& request = world.singleton<RenderRequest>();
    const MediaHooks* hooks = world.trySingleton<MediaHooks>();
    FrameInput f;
    f.environment = scene.environment;
    for (const auto& [node, mesh] : inNodeOrder<MeshRef>(world)) f.instances.push_back({mesh.first.mesh, mesh.second});
    for (const auto& [node, light] : inNodeOrder<LightRef>(world))
        f.lights.push_back(placeLight(scene.lights.at(static_cast<std::size_t>(light.first.light)), light.second));
    if (f.lights.empty()) f.lights.push_back(defaultSun());
    f.meshBounds = instanceBounds(scene, f.instances, BoxPer::Mesh);
    f.shadowBounds = f.meshBounds;
    nimbus::Aabb framed = instanceBounds(scene, f.instances, BoxPer::Primitive);
    if (hooks != nullptr && hooks->bounds) {
        const nimbus::Aabb media = hooks->bounds(world);
        f.shadowBounds.extend(media);
        framed.extend(media);
    }
    f.view = renderCamera(world, scene, request, framed);
    f.standardDepth = request.standardDepth;
    f.opaqueViewProjection = request.standardDepth ? standardProjection(f.view) * f.view.view : f.view.viewProjection;
    for (const auto& light : f.lights) f.shadowViews.push_back(gpu::makeLightViews(light, f.shadowBounds, f.view.origin));
    world.set(std::move(f));
}

void draw(ecs::World& world) {
    RenderState& state = world.singleton<RenderState>();
    if (!state.meshes) {
        state.meshes = std::make_unique<MeshRenderer>(*world.singleton<SceneAsset>().scene);
        state.composer = std::make_unique<Composer>();
    }
    const FrameInput& frame = world.singleton<FrameInput>();
    const MediaHooks* hooks = world.trySingleton<MediaHooks>();
    state.meshes->renderShadows(frame);
    // Media plugin, step 2 of its host contract: light slices before the opaque pass.
    const bool transmittance = hooks != nullptr && hooks->beforeOpaque && hooks->beforeOpaque(world, frame, *state.meshes);
    state.meshes->renderOpaque(frame, transmittance);
    // Media plugin, step 3: the medium against the scene depth, into its layer.
    state.mediaLayer = hooks != nullptr && hooks->afterOpaque ? hooks->afterOpaque(world, frame, *state.meshes) : MediaLayerRef{};
    state.composer->compose(state.meshes->sceneColor(), state.meshes->sceneDepth(), frame.view, frame.standardDepth, &state.mediaLayer);
}

void write(ecs::World& world) {
    const RenderRequest& request = world.singleton<RenderRequest>();
    const RenderState& state = world.singleton<RenderState>();
    const int w = request.width, h = request.height;
    writeExr(request.out, w, h, readRgbaTopDown(state.composer->output(), w, h));
    if (request.mediaOut.empty()) return;
    const MediaLayerRef& layer = state.mediaLayer;
    if (layer.color != 0) {
        writeExr(request.mediaOut, layer.width, layer.height, readRgbaTopDown(layer.color, layer.width, layer.height));
    } else {  // no medium: the layer that changes nothing (no radiance, transmittance 1)
        std::vector<float> clear(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0.0f);
        for (std::size_t i = 3; i < clear.size(); i += 4) clear[i] = 1.0f;
        writeExr(request.mediaOut, w, h, clear);
    }
}

}  // namespace

void RenderModule::import(ecs::World& world) {
    if (world.trySingleton<RenderRequest>() == nullptr) world.set(RenderRequest{});
    world.set(RenderState{});
    world.system("render.gather", ecs::Phase::PreStore, gather);
    world.system("render.draw", ecs::Phase::OnStore, draw);
    world.system("render.write", ecs::Phase::OnStore, write);
}

}  // namespace mini
