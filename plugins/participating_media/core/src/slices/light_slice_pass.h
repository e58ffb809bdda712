#pragma once
// The `light_slices` pass (shaders/media/light_slices.*).
#include <vector>

#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Where each view's slices are drawn: a view whose SliceView::resolution is below the array's
// goes to its own layers of a small array (`smallFirstLayer`, −1 for the others), at its own
// resolution in the small array's corner; light_slice_upscale_pass.h scales those up.
struct SmallSliceLayout {
    std::vector<int> smallFirstLayer;  // per view
    int size = 0;                      // the small array's side: the largest small view's
    int layers = 0;                    // its layers (0: no view is drawn small)
};

// Light slices (docs/design.md §3 light-slice system): every slice view renders all particles once,
// additively, into ceil(K/4) layers of one RGBA32F array. A view whose SliceView::resolution is
// below the array's is drawn at its own into the small array (SmallSliceLayout): a fragment costs
// the same either way, and a lamp's cube faces are covered by the particles around it.
class LightSlicePass {
public:
    struct Output {
        gpu::ResourceHandle slices;  // the array; a small view's layers are not written here
        gpu::ResourceHandle small;   // the small views' array, invalid when there is none
        SmallSliceLayout layout;     // where each view went
    };
    LightSlicePass();
    Output add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution, const ParticleGpuBuffer& buffer);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();  // core profile: one must be bound
};

}  // namespace nimbus::media
