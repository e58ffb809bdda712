#pragma once
// The `media_edge_stencil` pass (shaders/media/upsample/edge_stencil.frag).
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

// Mixed resolution (Cantlay, "High-Speed, Off-Screen Particles"): the pixels of a reduced media
// target whose four texels were not all computed at the pixel's depth (upsampleEdge in
// shaders/common/upsample.glsl) are marked, so the technique can draw its medium there again at
// full resolution behind a stencil test. The rest of the edge target says "not drawn" (alpha −1),
// so a host takes exactly the pixels drawn, whatever its own depth arithmetic.
// A framebuffer on an edge target: its colour and its stencil (as `color` and `stencil` resolve them).
gpu::Framebuffer edgeFramebuffer(GLuint color, GLuint stencil);
// The same, bound, with the viewport of a `viewport`-sized frame shifted so that the edge rect lands
// on the target (the rest is clipped): how a technique that draws in frame coordinates draws edges.
gpu::Framebuffer bindEdgeFramebuffer(GLuint color, GLuint stencil, glm::ivec4 rect, glm::ivec2 viewport);
// `state` where the edge stencil is 1, the stencil read only: how a technique draws its edges.
gpu::PipelineState onEdges(gpu::PipelineState state);

class MediaEdgeStencilPass {
public:
    MediaEdgeStencilPass();
    // After MediaDepthUsedPass: `depthUsed` is its texture for the reduced `target`.
    // `rect`: the pixels (x, y, width, height) within which it marks the edges; `whole`: pixels in
    // it it marks whatever the depths (MediaTarget::peak), width 0: none.
    EdgeTarget add(gpu::FrameGraph& graph, GraphFrame& context, gpu::ResourceHandle depthUsed, const MediaTarget& target, float threshold,
                   glm::ivec4 rect, glm::ivec4 whole);

private:
    gpu::FullscreenPass pass_;
    gpu::Sampler clampedNearest_;  // the gather reads past the reduced target's border
};

}  // namespace nimbus::media
