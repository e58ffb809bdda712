#pragma once
// The `raymarch` pass (after Jendersie; shaders/media/raymarch/raymarch.*): the voxel grid marched per
// pixel of the media target from a jittered start, up to the scene depth, until the view
// transmittance is spent. Light comes from the light slices and the mesh shadow maps.
#include <memory>

#include "common/lit_media_inputs.h"
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
    // What one march needs besides its target (the main pass's and the edges').
    struct March {
        const gpu::FullscreenPass* pass = nullptr;
        GraphFrame* context = nullptr;
        const RaymarchGrid* textures = nullptr;
        glm::vec3 corner{0.0f}, extent{0.0f};
        float voxel = 0.0f;
        int maxSteps = 1;
        bool rayleigh = false;
    };
    // The march of `textures`, which hold `grid` (whose corner is world space; the frame origin is the camera's).
    March march(GraphFrame& context, const VoxelGrid& grid, const RaymarchGrid& textures, int maxSteps);
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const March& march, const MediaTarget& target);
    // Over `size` texels of `framebuffer` under `state`: texel p is the viewport's pixel p · scale + offset.
    static void draw(const gpu::PassResources& resources, const LitMediaInputs& d, const March& m, GLuint framebuffer, glm::ivec2 size,
                     glm::vec2 scale, glm::vec2 offset, const gpu::PipelineState& state);

private:
    gpu::FullscreenPass pass_;
    std::unique_ptr<gpu::FullscreenPass> multiple_;  // MEDIA_MULTIPLE, made when a frame first needs it
};

}  // namespace nimbus::media
