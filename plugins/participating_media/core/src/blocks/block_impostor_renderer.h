#pragma once
// Depth impostors of a view's blocks (shaders/media/block_impostors.*), drawn by the camera's
// `block_impostors` pass and by `block_light_slices` for each light view.
#include "blocks/block_gpu_buffers.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/gl_objects.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// The atlas textures one impostor render writes (0: not written). depths (front, −back, τ) is
// always written; the camera also wants the weighted sums, the lights the depth moments.
struct ImpostorTargets {
    GLuint depths = 0;
    GLuint sums1 = 0;
    GLuint sums2 = 0;
    GLuint moments = 0;
};

// Renders a view's impostors into its atlas. Used by both the camera and the light passes.
class BlockImpostorRenderer {
public:
    BlockImpostorRenderer();
    void render(const BlockViewPlan& plan, std::size_t tileSet, const ImpostorTargets& targets, const BlockGpuBuffers& blocks,
                const ParticleGpuBuffer& particles) const;

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
