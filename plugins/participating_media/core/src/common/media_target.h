#pragma once
// Where a mode pass renders the medium this frame.
#include <glm/glm.hpp>

#include "nimbus/gpu/frame_graph.h"

namespace nimbus::media {

// The media target of one frame: full resolution, or reduced (Jendersie's offscreen particles) and
// upsampled afterwards. A mode pass renders into `size`; texel i stands for full-resolution
// position (i + 0.5) · fullResScale.
struct MediaTarget {
    glm::ivec2 size{1};
    glm::vec2 fullResScale{1.0f};
    const char* name = "media_color";
    // Valid: the passes blend straight over the host's output (GraphFrame::output) instead of
    // into a layer of their own, which spares the layer's clear and compose's full-screen pass.
    // Only at full resolution, and only for a technique whose entry says it draws over.
    gpu::ResourceHandle over;
};

}  // namespace nimbus::media
