#pragma once
// The light slices drawn from the particles one by one, as the modes without blocks have them:
// the plain pass (every particle into every slice of a view), or in deposit form (each particle
// into the slabs it reaches, then a running sum) where slice_deposit asks for it; then the frame's
// volumes added onto them, where it has some.
#include <memory>

#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/particle_set.h"
#include "common/shared_frame.h"
#include "slices/volume_slice_pass.h"

namespace nimbus::media {

class LightSlicePass;
class LightSliceDepositPass;
class LightSlicePrefixPass;

class ParticleSlices {
public:
    ParticleSlices();
    ~ParticleSlices();
    // The shared slice views' slices into context.slices; nothing where there are no views.
    // `noise`: the noise volumes' grid (volume_slice_pass.h), when the frame has noise volumes.
    void add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleSet& particles, const SharedFrame& shared,
             SliceDeposit deposit, const NoiseGridInput* noise = nullptr);

private:
    std::unique_ptr<LightSlicePass> plain_;  // each made when first needed
    std::unique_ptr<LightSliceDepositPass> deposit_;
    std::unique_ptr<LightSlicePrefixPass> prefix_;
    std::unique_ptr<VolumeSlicePass> volumes_;
};

}  // namespace nimbus::media
