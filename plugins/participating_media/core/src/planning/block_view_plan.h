#pragma once
// Blocks mode planning: where each block's impostor tile lies in a view's atlas (Umenhoffer and Szirmay-Kalos §2.1).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/block_partition.h"
#include "nimbus/media/impostor_atlas.h"

namespace nimbus::media {

struct alignas(16) GpuBlockTile {
    glm::vec4 rect;          // NDC rectangle in the view
    glm::vec4 atlas;         // tile in texels (width 0: not drawn)
    glm::vec4 centreRadius;  // origin-relative centre, mean particle radius
    glm::vec4 instance;      // x: ray-distance offset added to the tile's depths (instanced prototype; else 0);
                             // y: 1 when the tile has one texel per view pixel, on the pixel grid;
                             // z, w: the block's first impostor item and item count (w 0: an instance,
                             // whose particles are not in the item list)
    glm::vec4 lampSlices{0.0f};  // x: 1 when the lamps' slices hold the block's particles one by one
                                 // (blocksSeenWideFromLamps), not its light impostor; yzw free
    // A tile of an earlier frame read through this view (block_reuse.h): rows x, y and w (xyz) of
    // the map from this view's NDC (x, y, 1) to the tile's atlas texels; [0].w is 1 when it applies.
    glm::vec4 reproject[3]{};
};

// One view's impostor layout: where every block's tile is, and how big the atlas is.
struct BlockViewPlan {
    ImpostorView view;
    std::vector<GpuBlockTile> tiles;
    glm::ivec2 atlasSize{1, 1};
};

// `notDrawn` (per block, 1/0; empty: none): blocks whose tile this view leaves out (width 0), as a
// lamp's views leave out the blocks whose particles go into its slices one by one.
BlockViewPlan planBlockView(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin, float scale,
                            int maxAtlasSize, const std::vector<std::uint8_t>& notDrawn = {});

// Self-similar instancing: every block is drawn as a copy of block `prototype`, so the atlas holds
// one tile (the prototype's) that every block's rectangle maps onto, with its depths shifted by the
// block's distance from the prototype along the view.
BlockViewPlan planInstancedBlockView(const BlockPartition& partition, std::size_t prototype, const ImpostorView& view,
                                     const glm::dvec3& origin, float scale, int maxAtlasSize);

// The block whose bounding radius is the median: a representative prototype.
std::size_t choosePrototype(const BlockPartition& partition);

}  // namespace nimbus::media
