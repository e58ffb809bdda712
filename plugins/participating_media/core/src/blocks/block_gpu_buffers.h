#pragma once
// The frame's blocks on the GPU, for every blocks-mode pass.
#include <cstdint>
#include <utility>
#include <vector>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/gpu_bindings.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// The frame's blocks on the GPU: (particle, block) pairs in block order, every view's tiles (one
// range per view, all uploaded before the frame's first draw) and the camera's draw order.
// Nothing is rewritten between draws: llvmpipe does not order a buffer update after queued draws
// that read it (docs/design-notes.md).
class BlockGpuBuffers {
public:
    void uploadItems(const BlockPartition& partition);
    void uploadItems(const BlockPartition& partition, std::size_t onlyBlock);  // instancing: the prototype's particles
    void uploadTileSets(const std::vector<const BlockViewPlan*>& plans);
    void uploadDrawOrder(const std::vector<std::uint32_t>& blocks);
    void uploadOrderNeighbours(const std::vector<glm::uvec2>& lists);  // overlappingBlockLists
    // The particles the lamps' slices take one by one (blocksSeenWideFromLamps), for BlockSlicePass.
    void uploadLampSliceParticles(const std::vector<std::uint32_t>& particles);
    void bindLampSliceParticles() const;
    std::size_t lampSliceParticleCount() const { return lampSliceParticles_; }
    void bind(std::size_t tileSet) const;  // items, draw order, order neighbours and the tiles of one uploaded plan
    std::size_t itemCount() const { return items_; }

private:
    gpu::Buffer itemBuffer_, tileBuffer_, orderBuffer_, neighbourBuffer_, lampSliceBuffer_;
    std::size_t itemCapacity_ = 0, tileCapacity_ = 0, orderCapacity_ = 0, neighbourCapacity_ = 0, lampSliceCapacity_ = 0, items_ = 0,
                lampSliceParticles_ = 0;
    std::vector<std::pair<std::size_t, std::size_t>> tileRanges_;  // (byte offset, bytes) per tile set
};

}  // namespace nimbus::media
