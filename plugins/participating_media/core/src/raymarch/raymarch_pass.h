#pragma once
// The `raymarch` pass (after Jendersie; shaders/media/raymarch/raymarch.*): the voxel grid marched per
// pixel of the media target from a jittered start, up to the scene depth, until the view
// transmittance is spent. Light comes from the light slices and the mesh shadow maps.
#include <memory>

#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"
#include "raymarch/raymarch_grid.h"
#include "raymarch/voxel_grid.h"

namespace nimbus::media {

class RaymarchPass {
public:
    RaymarchPass();
    // Marches `textures`, which hold `grid` (whose corner is world space; the frame origin is the camera's).
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const VoxelGrid& grid, const RaymarchGrid& textures, int maxSteps,
                            const MediaTarget& target);

private:
    gpu::FullscreenPass pass_;
    std::unique_ptr<gpu::FullscreenPass> multiple_;  // MEDIA_MULTIPLE, made when a frame first needs it
};

}  // namespace nimbus::media
