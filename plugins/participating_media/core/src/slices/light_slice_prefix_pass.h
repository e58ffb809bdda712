#pragma once
// The `light_slice_prefix` pass (shaders/media/slices/light_slice_prefix.frag).
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Sums each view's slabs into the optical depth up to each of its slice planes.
class LightSlicePrefixPass {
public:
    LightSlicePrefixPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               gpu::ResourceHandle slabs);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
