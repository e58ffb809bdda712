#pragma once
// Where a mode pass renders the medium this frame.
#include <algorithm>
#include <cmath>

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
    // The viewport's pixels outside which the medium draws nothing (mediumRect, grown by the
    // upsampling's reach): the host composes the layer only there (MediaLayer::coverRect).
    glm::ivec4 cover{0};
    // A reduced target's lamp peaks (lampPeaks), drawn again at full resolution in modes that
    // draw edges; width 0: none.
    glm::ivec4 peak{0};
};

// How many pixels past a texel's own a reduced target's upsampling reads it (one texel's width and
// one more, for the gather's rounding); 0 at full resolution.
inline int upsampleReach(const MediaTarget& target) {
    const glm::vec2 s = target.fullResScale;
    return s == glm::vec2(1.0f) ? 0 : static_cast<int>(std::ceil(std::max(s.x, s.y))) + 1;
}

}  // namespace nimbus::media
