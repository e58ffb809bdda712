#include "slices/particle_slices.h"

#include <algorithm>

#include "nimbus/media/slice_plan.h"
#include "slices/light_slice_deposit_pass.h"
#include "slices/light_slice_pass.h"
#include "slices/light_slice_prefix_pass.h"
#include "slices/volume_slice_pass.h"

namespace nimbus::media {

ParticleSlices::ParticleSlices() = default;
ParticleSlices::~ParticleSlices() = default;

void ParticleSlices::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleSet& particles, const SharedFrame& shared,
                         SliceDeposit deposit, const NoiseGridInput* noise) {
    const std::vector<SliceView>& views = shared.sliceViews;
    if (views.empty()) return;
    // Deposit pays per slab a particle reaches; around a lamp inside the medium every particle
    // that reaches the lamp's plane covers a whole cube face in each, and drawing it once wins.
    const bool lampViews = std::any_of(views.begin(), views.end(), [](const SliceView& v) { return v.view.perspective; });
    const bool deposited = deposit == SliceDeposit::On || (deposit == SliceDeposit::Auto && !lampViews);
    if (deposited && LightSliceDepositPass::supported()) {
        std::vector<std::uint32_t> pieces;
        std::vector<int> firstPiece{0};
        for (const SliceView& v : views) {
            appendSlabPieces(particles, v.view, context.host.camera.origin, v.slices, pieces, v.seedView >= 0 ? 1 : 0);
            firstPiece.push_back(static_cast<int>(pieces.size()));
        }
        if (!deposit_) deposit_ = std::make_unique<LightSliceDepositPass>();
        if (!prefix_) prefix_ = std::make_unique<LightSlicePrefixPass>();
        const gpu::ResourceHandle slabs =
            deposit_->add(graph, views, shared.sliceResolution, *shared.buffer, std::move(pieces), std::move(firstPiece));
        context.slices = prefix_->add(graph, views, shared.sliceResolution, slabs);
    } else {
        if (!plain_) plain_ = std::make_unique<LightSlicePass>();
        context.slices = plain_->add(graph, views, shared.sliceResolution, *shared.buffer);
    }
    if (shared.volumeCount > 0) {
        if (!volumes_) volumes_ = std::make_unique<VolumeSlicePass>();
        context.slices = volumes_->add(graph, context.slices, views, shared.sliceResolution, *shared.volumes, noise);
    }
}

}  // namespace nimbus::media
