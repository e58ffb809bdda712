#pragma once
// The `light_slice_pairs` pass (shaders/media/slices/light_slice_pairs.frag).
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Rewrites the slices, packed four planes to a layer as the slice passes draw them, two planes to a
// layer beside their predecessors: the layout every reader of the slices takes
// (media/host/light_transmittance.glsl), which then interpolates between two planes with one fetch.
// View v's plane k lands in layer 2·v.firstLayer + k/2. Does not change any value.
class LightSlicePairsPass {
public:
    LightSlicePairsPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution, gpu::ResourceHandle packed);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
