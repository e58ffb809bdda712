#pragma once
// The `media_depth_used` pass (shaders/media/upsample/depth_used.frag).
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

// Jendersie's offscreen particles: the view depth each reduced texel of the media target used, which the compose pass's
// depth-aware upsampling compares with each full-resolution pixel's.
class MediaDepthUsedPass {
public:
    MediaDepthUsedPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const MediaTarget& target);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
