#pragma once
// The `volume_slices` pass (shaders/media/slices/volume_slices.frag): every volume's optical depth
// added onto the light slices the particles left, so the medium's light and the meshes' medium
// shadows see the volumes as they see particles.
//
// Does not: create the slices (a particle slice pass does, with or without particles).
#include <vector>

#include "common/volume_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "slices/slice_view.h"

namespace nimbus::media {

class VolumeSlicePass {
public:
    VolumeSlicePass();
    // Adds onto `slices` (written, not replaced); returns the same resource.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views, int resolution,
                            const VolumeGpuBuffer& volumes);

private:
    gpu::FullscreenPass pass_;
};

}  // namespace nimbus::media
