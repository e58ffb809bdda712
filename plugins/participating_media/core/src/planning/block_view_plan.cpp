#include "planning/block_view_plan.h"

#include <algorithm>
#include <numeric>

namespace nimbus::media {

BlockViewPlan planBlockView(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin, float scale,
                            int maxAtlasSize, const std::vector<std::uint8_t>& notDrawn) {
    BlockViewPlan plan;
    plan.view = view;
    const std::vector<BlockFootprint> footprints = blockFootprints(partition, view, origin);
    std::vector<glm::ivec2> sizes = tileSizes(footprints, view.viewport, scale);
    for (std::size_t b = 0; b < notDrawn.size() && b < sizes.size(); ++b)
        if (notDrawn[b] != 0) sizes[b] = glm::ivec2(0);
    const AtlasLayout layout = packAtlas(sizes, maxAtlasSize);
    plan.atlasSize = glm::ivec2(layout.width, layout.height);
    plan.tiles.resize(partition.blocks.size());
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        const AtlasTile& t = layout.tiles[b];
        plan.tiles[b].rect = footprints[b].rect;
        plan.tiles[b].atlas = glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.width),
                                        static_cast<float>(t.height));
        plan.tiles[b].centreRadius = glm::vec4(glm::vec3(partition.blocks[b].centre - origin), partition.blocks[b].meanParticleRadius);
        // Texel centres are pixel centres when the snapped rectangle's pixels are the tile's texels.
        const glm::vec2 pixels = glm::round(rectanglePixels(footprints[b].rect, view.viewport));
        const bool onPixelGrid = t.width > 0 && pixels == glm::vec2(static_cast<float>(t.width), static_cast<float>(t.height));
        // Items are uploaded block by block in partition order (uploadItems), so a block's items
        // are its slice of `order`. Floats hold the indices exactly up to 2^24; beyond, no list.
        const Block& block = partition.blocks[b];
        const bool listed = std::uint64_t{block.first} + block.count <= (std::uint64_t{1} << 24);
        plan.tiles[b].instance = glm::vec4(0.0f, onPixelGrid ? 1.0f : 0.0f, listed ? static_cast<float>(block.first) : 0.0f,
                                           listed ? static_cast<float>(block.count) : 0.0f);
    }
    return plan;
}

BlockViewPlan planInstancedBlockView(const BlockPartition& partition, std::size_t prototype, const ImpostorView& view,
                                     const glm::dvec3& origin, float scale, int maxAtlasSize) {
    // Every instance has the prototype's shape: its sphere around its own centre.
    BlockPartition shapes = partition;
    for (Block& b : shapes.blocks) b.radius = partition.blocks[prototype].radius;
    BlockViewPlan plan;
    plan.view = view;
    const std::vector<BlockFootprint> footprints = blockFootprints(shapes, view, origin);
    std::vector<glm::ivec2> sizes(footprints.size(), glm::ivec2(0));
    sizes[prototype] = tileSizes({footprints[prototype]}, view.viewport, scale).front();
    const AtlasLayout layout = packAtlas(sizes, maxAtlasSize);
    const AtlasTile& t = layout.tiles[prototype];
    plan.atlasSize = glm::ivec2(layout.width, layout.height);
    const glm::dmat4 viewMatrix(view.view);
    auto distance = [&](const glm::dvec3& centre) {
        const glm::dvec3 c(viewMatrix * glm::dvec4(centre - origin, 1.0));
        return view.perspective ? glm::length(c - glm::dvec3(viewMatrix * glm::dvec4(glm::dvec3(view.eye), 1.0))) : -c.z;
    };
    const double prototypeDistance = distance(partition.blocks[prototype].centre);
    plan.tiles.resize(partition.blocks.size());
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        GpuBlockTile& tile = plan.tiles[b];
        tile.rect = footprints[b].rect;
        const bool visible = tile.rect.z > tile.rect.x && t.width > 0;
        tile.atlas = visible ? glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.width),
                                         static_cast<float>(t.height))
                             : glm::vec4(0.0f);
        tile.centreRadius = glm::vec4(glm::vec3(partition.blocks[b].centre - origin), partition.blocks[prototype].meanParticleRadius);
        tile.instance = glm::vec4(static_cast<float>(distance(partition.blocks[b].centre) - prototypeDistance), 0.0f, 0.0f, 0.0f);
    }
    // The prototype's own tile must exist for its impostor to be rendered, even when it is off-view.
    if (t.width > 0) plan.tiles[prototype].atlas = glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y),
                                                             static_cast<float>(t.width), static_cast<float>(t.height));
    return plan;
}

std::size_t choosePrototype(const BlockPartition& partition) {
    std::vector<std::size_t> order(partition.blocks.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return partition.blocks[a].radius < partition.blocks[b].radius; });
    return order.empty() ? 0 : order[order.size() / 2];
}

}  // namespace nimbus::media
