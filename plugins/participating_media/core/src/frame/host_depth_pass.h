#pragma once
// The `media_host_depth` pass (shaders/media/frame/host_depth.frag): a standard-Z host depth re-encoded
// as reversed Z for the plugin's camera, into an R32F texture the media passes read.
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/view.h"

namespace nimbus::media {

class HostDepthPass {
public:
    HostDepthPass();
    // `camera` gives the planes and the size; returns the re-encoded depth.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, gpu::ResourceHandle hostDepth, const gpu::View& camera);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
