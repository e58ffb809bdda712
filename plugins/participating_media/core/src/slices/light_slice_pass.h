#pragma once
// The `light_slices` pass (shaders/media/light_slices.*).
#include <vector>

#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Light slices (docs/design.md §3 light-slice system): every slice view renders all particles once,
// additively, into ceil(K/4) layers of one RGBA32F array. A view whose SliceView::resolution is
// below the array's is drawn at its own into a small array, then scaled up into its layers
// (bilinear, as the slices are read): a fragment costs the same either way, and a lamp's cube faces
// are covered by the particles around it.
class LightSlicePass {
public:
    LightSlicePass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               const ParticleGpuBuffer& buffer);

private:
    void drawView(GLuint framebuffer, GLuint slices, const SliceView& view, int resolution, const ParticleGpuBuffer& buffer);
    gpu::Program program_;
    gpu::Texture small_;  // the small views' layers before they are scaled up (resized as needed)
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();  // core profile: one must be bound
};

}  // namespace nimbus::media
