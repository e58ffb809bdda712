#pragma once
// The `block_seam_stencil` pass (shaders/media/blocks/block_seam_stencil.frag): the seam mask as stencil 1
// at the media target's size, where the composite shades a seam run exactly.
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"

namespace nimbus::media {

class BlockSeamStencilPass {
public:
    BlockSeamStencilPass();
    // `mask` from BlockSeamMaskPass, with `cell` media texels per mask texel.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, gpu::ResourceHandle mask, const MediaTarget& target, int cell);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
