#pragma once
// The splat floor (docs/design.md §6, `sandbox render --floor`): how long this GL implementation takes to
// blend every particle's full-resolution billboard once, with a trivial shader, into an RGBA32F
// target the size of the image. A mode's frame time divided by it says how far the frame is from
// what any splatting renderer pays just to touch the particles' pixels.
//
// Does not: depend on the mode or its settings (the same yardstick for every setting of a scene).
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/view.h"
#include "common/frame_blocks.h"
#include "common/particle_buffer.h"

namespace nimbus::media {

class SplatFloor {
public:
    SplatFloor();
    // Median ms over `repeats` GPU-synchronised draws of `buffer`'s particles seen through `view`.
    double measure(const ParticleGpuBuffer& buffer, const gpu::View& view, int repeats);

private:
    void draw(const ParticleGpuBuffer& buffer, GLuint framebuffer, int width, int height);

    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
    FrameBlocks frameBlocks_;
};

}  // namespace nimbus::media
