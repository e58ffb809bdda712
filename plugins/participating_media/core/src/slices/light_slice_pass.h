#pragma once
// The `light_slices` pass (shaders/media/light_slices.*).
#include <vector>

#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Light slices (docs/design.md §3 light-slice system): every slice view renders all particles once,
// additively, into ceil(K/4) layers of one RGBA32F array, at its own texels (sliceTexels: a lamp's
// cube faces may take fewer than the sun's view) in the first ones of its layers.
class LightSlicePass {
public:
    LightSlicePass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution, const ParticleGpuBuffer& buffer);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();  // core profile: one must be bound
};

}  // namespace nimbus::media
