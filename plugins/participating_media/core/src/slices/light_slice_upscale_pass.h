#pragma once
// The `light_slice_upscale` pass (shaders/media/slices/light_slice_upscale.*).
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/light_slice_pass.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Scales the views that light_slice_pass.h drew small up into their layers of the slice array,
// bilinear with each view's edge clamped, as the slices are read. One framebuffer bind and one
// instanced draw a view (gl_Layer from the vertex shader, ARB_shader_viewport_layer_array), where
// a blit a layer cost about as much again as drawing the particles; without the extension, a draw
// a layer. Not a blit: a linear blit of a view in the small array's corner reads past its edge.
//
// Does not: touch a view drawn at the array's resolution.
class LightSliceUpscalePass {
public:
    // `layered`: draw every layer of a view at once with gl_Layer (the default where the extension
    // is there), else one layer a draw.
    explicit LightSliceUpscalePass(bool layered = supported());
    static bool supported();
    // `drawn`: LightSlicePass::add's output; returns the slice array with every view in it.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                            const LightSlicePass::Output& drawn);

private:
    bool layered_;
    gpu::Program program_;
    gpu::Sampler bilinear_ = gpu::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
