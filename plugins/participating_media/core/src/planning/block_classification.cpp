// Blocks mode planning: which blocks the composite draws with its exact cut, its own-particle
// shading and its exact shading (planning/block_classification.h).
#include "planning/block_classification.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_access.hpp>

namespace nimbus::media {

std::vector<std::uint8_t> blocksNearMeshes(const BlockPartition& partition, const std::vector<OccluderBox>& meshes) {
    std::vector<std::uint8_t> near(partition.blocks.size(), 0);
    // Only meshes whose axis-aligned hull meets the blocks' reach at all are tested block by block
    // (a level of many meshes around one cloud).
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const Block& block : partition.blocks) {
        const double reach = block.radius + block.meanParticleRadius;
        lo = glm::min(lo, block.centre - reach);
        hi = glm::max(hi, block.centre + reach);
    }
    std::vector<const OccluderBox*> candidates;
    for (const OccluderBox& box : meshes) {
        const glm::dvec3 hull = axisAlignedHalf(box);
        if (glm::all(glm::lessThanEqual(box.centre - hull, hi)) && glm::all(glm::greaterThanEqual(box.centre + hull, lo)))
            candidates.push_back(&box);
    }
    for (std::size_t b = 0; b < partition.blocks.size() && !candidates.empty(); ++b) {
        const Block& block = partition.blocks[b];
        const double reach = block.radius + block.meanParticleRadius;
        for (const OccluderBox* candidate : candidates) {
            if (squaredDistance(*candidate, block.centre) <= reach * reach) {
                near[b] = 1;
                break;
            }
        }
    }
    return near;
}

namespace {

// The NDC rectangle (min xy, max zw) a box covers in `view`; the whole screen where it reaches
// behind the eye.
glm::dvec4 screenRectangle(const OccluderBox& box, const gpu::View& view) {
    glm::dvec4 rect(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
    const glm::dmat4 viewProjection(view.viewProjection);
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 p = box.centre - view.origin;
        for (int k = 0; k < 3; ++k) p += box.axis[k] * ((corner >> k) & 1 ? box.half[k] : -box.half[k]);
        const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
        if (!(clip.w > 1e-9)) return glm::dvec4(-1.0, -1.0, 1.0, 1.0);
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        rect = glm::dvec4(glm::min(glm::dvec2(rect), ndc), glm::max(glm::dvec2(rect.z, rect.w), ndc));
    }
    return rect;
}

}  // namespace

std::vector<std::uint8_t> blocksShadedExactly(const BlockPartition& partition, const std::vector<OccluderBox>& meshes,
                                              const BlockViewPlan& cameraPlan, const gpu::View& view) {
    std::vector<std::uint8_t> exact(partition.blocks.size(), 0);
    // One mesh at a time: the blocks near it, and whether it passes among the blocks at all.
    std::vector<glm::dvec4> rects;
    std::vector<double> farthest;  // a mesh box's farthest distance from the eye
    for (const OccluderBox& box : meshes) {
        const std::vector<std::uint8_t> near = blocksNearMeshes(partition, {box});
        if (std::find(near.begin(), near.end(), std::uint8_t{1}) == near.end()) continue;
        for (std::size_t b = 0; b < exact.size(); ++b) exact[b] |= near[b];
        rects.push_back(screenRectangle(box, view));
        double hull = 0.0;
        for (int k = 0; k < 3; ++k) hull += box.half[k] * box.half[k];
        farthest.push_back(glm::length(box.centre - view.origin) + std::sqrt(hull));
    }
    for (std::size_t b = 0; b < partition.blocks.size() && !rects.empty(); ++b) {
        if (!(cameraPlan.tiles[b].atlas.z > 0.0f)) continue;  // not drawn (off the screen)
        const glm::vec4 rect = cameraPlan.tiles[b].rect;
        const Block& block = partition.blocks[b];
        const double nearest = glm::length(block.centre - view.origin) - block.radius;
        for (std::size_t m = 0; m < rects.size() && !exact[b]; ++m) {
            const bool overlaps = rect.x <= rects[m].z && rect.z >= rects[m].x && rect.y <= rects[m].w && rect.w >= rects[m].y;
            if (overlaps && nearest < farthest[m]) exact[b] = 1;
        }
    }
    return exact;
}

bool sliceViewResolves(const gpu::GpuLightView& v, const glm::dvec3& centre, double radius, double sigma) {
    const double spacing = (static_cast<double>(v.params.z) - v.params.y) / std::max(static_cast<double>(v.params.w), 1.0);
    const double depth = -(glm::dmat4(v.view) * glm::dvec4(centre, 1.0)).z;
    const double texel = v.params2.y * (v.params.x > 0.5f ? std::max(depth, 0.0) : 1.0);
    return spacing <= 2.0 * radius && texel <= radius && sigma * std::max(spacing, texel) <= 2.0;
}

std::vector<std::uint8_t> blocksOfUnresolvedParticles(const BlockPartition& partition, const ParticleSet& particles,
                                                       const std::vector<gpu::GpuLightView>& views, const glm::dvec3& origin) {
    std::vector<std::uint8_t> unresolved(partition.blocks.size(), 0);
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        const Block& block = partition.blocks[b];
        if (block.count == 0 || block.count > kMaxOwnShadedBlockParticles) continue;
        const glm::dvec3 centre = block.centre - origin;
        for (std::uint32_t k = block.first; k < block.first + block.count && !unresolved[b]; ++k) {
            const std::uint32_t i = partition.order[k];
            for (const gpu::GpuLightView& v : views) {
                if (!sliceViewResolves(v, centre, particles.radius[i], particles.sigma[i])) {
                    unresolved[b] = 1;
                    break;
                }
            }
        }
    }
    return unresolved;
}

}  // namespace nimbus::media
