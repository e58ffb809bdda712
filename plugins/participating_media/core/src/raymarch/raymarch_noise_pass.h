#pragma once
// The `raymarch_noise` pass (shaders/media/raymarch/raymarch_noise.comp): every noise volume's
// medium evaluated on the GPU at the raymarch grid's voxel centres, added into the grid and into
// its noise texture (raymarch_grid.h). The noise is the function the reference evaluates on the CPU,
// to the bit (noise_field.h).
//
// Does not: touch constant volumes or particles (the CPU grid has them).
#include <vector>

#include "common/volume_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/shader_program.h"
#include "raymarch/raymarch_grid.h"

namespace nimbus::media {

class RaymarchNoisePass {
public:
    RaymarchNoisePass();
    // After the upload pass wrote `grid` and `buffer`; `origin` is the frame origin.
    void add(gpu::FrameGraph& graph, const RaymarchGrid& grid, const VoxelGrid& cpu, const std::vector<Volume>& volumes,
             const VolumeGpuBuffer& buffer, const glm::dvec3& origin);

private:
    gpu::Program program_;
};

}  // namespace nimbus::media
