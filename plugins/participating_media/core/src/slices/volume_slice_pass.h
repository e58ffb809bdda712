#pragma once
// The `volume_slices` pass (shaders/media/slices/volume_slices.frag): every volume's optical depth
// added onto the light slices the particles left, so the medium's light and the meshes' medium
// shadows see the volumes as they see particles.
//
// Constant volumes are exact (σ times the chord before each plane); noise volumes come from a grid
// of their σ_t (raymarch_grid.h), marched a voxel a step along each texel's ray.
//
// Does not: create the slices (a particle slice pass does, with or without particles).
#include <memory>
#include <vector>

#include "common/volume_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "slices/slice_view.h"

namespace nimbus::media {

// The noise volumes' σ_t on a grid (frame-relative corner and extent). The texture is read when the
// graph runs, after the passes that make and fill it.
struct NoiseGridInput {
    const gpu::Texture* texture = nullptr;
    glm::vec3 corner{0.0f}, extent{0.0f};
    float voxel = 0.0f;
};

class VolumeSlicePass {
public:
    VolumeSlicePass();
    // Adds onto `slices` (written, not replaced); returns the same resource. `noise` must outlive
    // the graph's execution when given.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, gpu::ResourceHandle slices, const std::vector<SliceView>& views, int resolution,
                            const VolumeGpuBuffer& volumes, const NoiseGridInput* noise);

private:
    gpu::FullscreenPass pass_;
    std::unique_ptr<gpu::FullscreenPass> noisePass_;  // VOLUME_NOISE_GRID, made when a frame first has noise
};

}  // namespace nimbus::media
