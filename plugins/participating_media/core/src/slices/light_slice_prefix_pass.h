#pragma once
// The `light_slice_prefix` pass (shaders/media/slices/light_slice_prefix.frag).
#include <array>
#include <memory>
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/slice_plan.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Sums each view's slabs into the optical depth up to each of its slice planes.
class LightSlicePrefixPass {
public:
    LightSlicePrefixPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               gpu::ResourceHandle slabs);

private:
    // The program for a view of `slices` slices (its count is compile-time), made when first needed.
    const gpu::FullscreenPass& passFor(int slices);
    std::array<std::unique_ptr<gpu::FullscreenPass>, kMaxSlices + 1> passes_;
};

}  // namespace nimbus::media
