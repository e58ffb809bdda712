#pragma once
// The `light_slice_intervals` pass (shaders/media/slices/light_slice_intervals.frag).
#include <vector>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// Rewrites the slices, packed four planes to a layer as the slice passes draw them, one interval
// between planes to a layer: the optical depth at its two ends and at the planes either side of
// them. That is the layout every reader of the slices takes (media/host/light_transmittance.glsl),
// which then interpolates a cubic across the interval with one fetch. View v's interval k (between
// planes k and k + 1, plane 0 the near one) lands in layer 4·v.firstLayer + k. Does not change any
// value. One interval to a layer, not two: the second's slope at its far end would have to be
// one-sided, and at fast's plane spacing that erred more than a straight line (docs/design-notes.md).
// The view's first layer in the intervals array: four for each of its packed layers.
inline int intervalLayer(const SliceView& v) { return 4 * v.firstLayer; }

class LightSliceIntervalsPass {
public:
    LightSliceIntervalsPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution, gpu::ResourceHandle packed);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
