#pragma once
// Rendering:
//   PreStore render.gather  FrameInput from the world: camera view, lights, instances, bounds, shadow views
//   OnStore  render.draw    shadow maps → [media: light slices] → opaque → [media: layer] → compose
//   OnStore  render.write   the composed image (and the media layer) as EXR
// A media module plugs in through the MediaHooks singleton; without one the frame is meshes only.
#include <filesystem>
#include <functional>
#include <memory>

#include "compose.h"
#include "frame_input.h"
#include "mesh_renderer.h"
#include "modules/components.h"

namespace mini {

struct RenderRequest {
    int width = 1280, height = 720;
    std::filesystem::path out;       // composed image (.exr)
    std::filesystem::path mediaOut;  // the media layer (.exr); empty: not written
    bool standardDepth = false;      // draw the opaque scene with standard depth (the plugin re-encodes it)
};

// What a media module hands the render module (every member optional):
struct MediaHooks {
    // PreStore: the medium's world box; the shadow views and a framing camera cover it too.
    std::function<nimbus::Aabb(ecs::World&)> bounds;
    // OnStore, after the shadow maps: render the light slices and bind them for the mesh shader;
    // true: draw the opaque pass with MEDIA_LIGHT_TRANSMITTANCE.
    std::function<bool(ecs::World&, const FrameInput&, const MeshRenderer&)> beforeOpaque;
    // OnStore, after the opaque pass (scene depth ready): the media layer to compose.
    std::function<MediaLayerRef(ecs::World&, const FrameInput&, const MeshRenderer&)> afterOpaque;
};

// GL state of the render module, created on the first render.draw (the context must be current).
struct RenderState {
    std::unique_ptr<MeshRenderer> meshes;
    std::unique_ptr<Composer> composer;
    MediaLayerRef mediaLayer;  // this frame's, when a media module gave one
};

struct RenderModule {
    static void import(ecs::World& world);
};

}  // namespace mini
