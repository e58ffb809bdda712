#pragma once
// The participating-media plugin as a mini_host module: one import call registers its components,
// singletons and systems in mini_host's phases, and fills the render module's MediaHooks. It uses
// the plugin only through its host contract (nimbus/media/host.h) and its glTF part.
//
//   PostLoad  media.spawn   parse each node's extension (plugin glTF part); StaticCloud / VolumeNode / Emitter components
//   OnUpdate  media.emit    step every Emitter to the scene time, in the plugin's fixed step
//   PreStore  media.gather  static clouds then emitters, in node order, into the frame's ParticleSet;
//                           volumes placed by their nodes' transforms
//   OnStore   (hooks)       light slices before the opaque pass, the media layer after it
//
// Import it before RenderModule: render.gather asks for the media's bounds in the same phase.
#include <memory>

#include "ecs/world.h"
#include "nimbus/media/emitter_simulation.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/media_scene.h"

namespace mini {

// Components.
struct StaticCloud {
    std::size_t mediaNode = 0;  // index into MediaState::scene.nodes
};
struct VolumeNode {
    std::size_t mediaNode = 0;
};
struct Emitter {
    std::size_t mediaNode = 0;
    nimbus::media::EmitterSimulation simulation;
    long long steps = 0;  // fixed steps taken so far
};

// Singletons.
struct MediaSettings {
    nimbus::media::MediaRenderSettings settings;  // zero: the plugin's defaults (its exact tier)
};
struct MediaState {
    std::unique_ptr<nimbus::media::GltfDocument> document;
    nimbus::media::MediaScene scene;
    nimbus::media::ParticleSet particles;  // this frame's
    std::vector<nimbus::media::Volume> volumes;  // this frame's
    std::unique_ptr<nimbus::media::MediaRenderer> renderer;  // created by the first frame with a medium
    bool empty() const { return particles.empty() && volumes.empty(); }
    nimbus::media::HostFrame frame;             // this frame's, for both of the renderer's calls
    nimbus::media::HostShadowMaps shadows;      // what frame.shadows points to
};

struct MediaModule {
    static void import(ecs::World& world);
};

}  // namespace mini
