#pragma once
// The `light_slice_deposit` pass (shaders/media/light_slice_deposit.*).
#include <cstdint>
#include <vector>

#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// The light slices in deposit form (the fast tiers), two passes that replace LightSlicePass: each
// particle is drawn once into each slab between two slice planes it reaches, as one R32F layer per
// slab (slice_plan.h appendSlabPieces); the prefix pass sums the slabs into the RGBA32F slices
// LightSlicePass writes. Per fragment one float instead of ceil(K/4) RGBA targets and K erf values.
// Needs ARB_shader_viewport_layer_array (gl_Layer from the vertex shader).
class LightSliceDepositPass {
public:
    LightSliceDepositPass();
    static bool supported();
    // `pieces`: every view's pieces, view v's from firstPiece[v] (firstPiece has views.size() + 1 entries).
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               const ParticleGpuBuffer& buffer, std::vector<std::uint32_t> pieces, std::vector<int> firstPiece);

private:
    gpu::Program orthographic_, perspective_;  // light_slice_deposit.* without and with LIGHT_PERSPECTIVE
    gpu::Buffer pieces_;
    std::size_t capacity_ = 0;
    std::vector<std::uint32_t> staging_;  // this frame's pieces, uploaded when the pass runs
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
